#pragma once
// The body of BENCHMARK_MAIN, for the benchmark programs whose main does something first
// (OpenBLAS's kernels and the OpenMP regions as `contact-suite` has them).

#include <benchmark/benchmark.h>

namespace cs::bench {

/// Runs the registered benchmarks with the command line's options; 1 on an unknown option.
inline int run_benchmarks(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace cs::bench

#pragma once
// `contact-suite report --results FILE --out DIR [--baseline OLD] [--study-data DIR]
//                       [--bench BENCH.json ...] [--no-figures]`:
// turns a results.json into DIR/report.md (with figures/), DIR/results.csv and, with a
// baseline, DIR/regression.md; with Google Benchmark JSON of bench_contact_algorithms, report.md
// gains section 8, "Benchmarks". Reads results and benchmark files only; never runs the solver.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `report` subcommand on `app`. Bad input (a missing, non-JSON, truncated or
/// wrong-version results file, a bench file that is missing, malformed or holds no Contact
/// benchmark, unreadable study data, an unwritable DIR) throws an exception
/// derived from std::invalid_argument (cs::reports::ReportError): one line, exit code 2, and
/// DIR left as it was.
void add_report_command(CLI::App& app);

}  // namespace cs::apps

#pragma once
// The contact methods as bench/bench_contact_algorithms names its benchmarks: the solver's
// methods, in the solver's order. Each is named, drawn and coloured as the study's algorithm it is
// (schema/case_axes.hpp), except LM: the solver's Lagrange-multiplier method is both the study's
// LMP and PLM (they coincide without friction). A table in the vocabulary's form
// (schema/name_table.hpp), so that to_string, parse and values work on it.

#include <cstdint>
#include <string_view>

#include "schema/case_axes.hpp"

namespace cs::reports {

enum class BenchMethod : std::uint8_t { PM, AL, LM, MPC };

/// The study's algorithm a benchmarked method is (LM: LMP, the first of its study column).
constexpr schema::Algorithm study_algorithm(BenchMethod m) {
  switch (m) {
    case BenchMethod::PM:
      return schema::Algorithm::PM;
    case BenchMethod::AL:
      return schema::Algorithm::AL;
    case BenchMethod::LM:
      return schema::Algorithm::LMP;
    case BenchMethod::MPC:
      return schema::Algorithm::MPC;
  }
  return schema::Algorithm::AL;
}

constexpr std::string_view axis_name(BenchMethod) {
  return "benchmarked contact method";
}

/// The study's algorithm's names, but the solver's own for LM, which the study splits in two.
constexpr schema::AxisEntry entry(BenchMethod m) {
  switch (m) {
    case BenchMethod::LM:
      return {"LM", "", ""};
    case BenchMethod::PM:
    case BenchMethod::AL:
    case BenchMethod::MPC:
      return entry(study_algorithm(m));
  }
  return {};  // past the last method: where values<BenchMethod>() stops
}

}  // namespace cs::reports

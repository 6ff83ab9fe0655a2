#pragma once
// The CI gate: compares a results file with a committed baseline, case by case and row by row.
//
// Two checks, as verification suites of commercial codes make them:
//   1. regression: every graded value is within a relative tolerance of the baseline value
//      (per quantity, from the baseline file; default kDefaultGateTolerance), and a case that
//      converged in the baseline still converges;
//   2. analytic reference: every row's grade (Eq. 46) is no worse than the baseline's, and a
//      row that was converging (or, for the singular problems, diverging, Eq. 47) still is. A
//      grade that drops while its value moved by round-off alone (within the quantity's
//      tolerance and kDefaultGateTolerance) sat on a band's edge and is not a failure.
// The baseline file (schema/baseline_file.hpp) is written by --update from a results file; it
// keeps the tolerances it had.

#include <map>
#include <string>
#include <vector>

#include "schema/baseline_file.hpp"
#include "suites/case_result.hpp"
#include "suites/row_verdict.hpp"

namespace cs::suites {

using schema::Baseline;

/// One failed check.
struct GateFailure {
  std::string id;      ///< case id or row id
  std::string check;   ///< "value drift", "status", "grade", "converging", "diverging"
  std::string before;  ///< baseline value / grade / status
  std::string after;   ///< new value / grade / status
  std::string detail;  ///< e.g. the relative drift and the tolerance
  std::vector<std::string> row_ids;  ///< the rows it concerns (a case's failure: all its rows)
};

/// The one-line reason of a failure, e.g. "value drift of H_p/M/Q4/AL/ss sigma_c: now
/// 1.2705, baseline 1.2704 (relative drift 7.9e-05 > tolerance 1e-06)".
std::string failure_line(const GateFailure& failure);

/// The gate's verdict.
struct GateReport {
  int cases_checked = 0;
  int rows_checked = 0;
  std::vector<GateFailure> failures;
  bool passed() const { return failures.empty(); }
};

/// A baseline from results, with `tolerances` (kept from an old baseline by --update).
Baseline make_baseline(const std::vector<CaseResult>& cases,
                       const schema::GateTolerances& tolerances);

/// Runs both checks. Throws SuiteInputError listing the cases found in only one of the two
/// (the files must cover the same cases).
GateReport run_gate(const Baseline& baseline, const std::vector<CaseResult>& results);

/// The failures as a Markdown-style text table (empty string when the gate passed).
std::string format_gate_failures(const GateReport& report);

}  // namespace cs::suites

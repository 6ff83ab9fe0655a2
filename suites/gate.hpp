#pragma once
// The CI gate: compares a results file with a committed baseline, case by case and row by row.
//
// Two checks, as verification suites of commercial codes make them:
//   1. regression: every graded value is within a relative tolerance of the baseline value
//      (per quantity, from the baseline file; default kDefaultGateTolerance), and a case that
//      converged in the baseline still converges;
//   2. analytic reference: every row's grade (Eq. 46) is no worse than the baseline's, and a
//      row that was converging (or, for the singular problems, diverging, Eq. 47) still is.
// The baseline file (schema `contact-suite/baseline`, version 2: its case records carry the
// nodal stress recovery) is written by --update from a results file; it keeps the tolerances
// it had, also from a baseline of an older version.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "suites/case_result.hpp"
#include "suites/row_verdict.hpp"

namespace cs::suites {

inline constexpr const char* kBaselineSchemaName = "contact-suite/baseline";
inline constexpr int kBaselineSchemaVersion = 2;
/// Survives compiler and BLAS differences; far below any change that matters to a grade.
inline constexpr double kDefaultGateTolerance = 1e-6;

/// A baseline: per-case values and statuses, per-row verdicts, tolerances.
struct Baseline {
  double default_tolerance = kDefaultGateTolerance;
  std::map<std::string, double> tolerances;  ///< per quantity name
  std::vector<CaseResult> cases;             ///< values, grades and statuses only
  std::vector<RowVerdict> rows;
};

/// One failed check.
struct GateFailure {
  std::string id;      ///< case id or row id
  std::string check;   ///< "value drift", "status", "grade", "converging", "diverging"
  std::string before;  ///< baseline value / grade / status
  std::string after;   ///< new value / grade / status
  std::string detail;  ///< e.g. the relative drift and the tolerance
};

/// The gate's verdict.
struct GateReport {
  int cases_checked = 0;
  int rows_checked = 0;
  std::vector<GateFailure> failures;
  bool passed() const { return failures.empty(); }
};

/// Reads a baseline document; throws SuiteInputError naming the problem (schema, version,
/// malformed record).
Baseline baseline_from_json(const nlohmann::json& doc);
/// The tolerances of a baseline of any version of the schema: {default, per quantity}. What
/// --update keeps when it rewrites an older baseline. Throws SuiteInputError as above.
std::pair<double, std::map<std::string, double>> baseline_tolerances_from_json(
    const nlohmann::json& doc);
/// A baseline from results, keeping `tolerances` (and the default) from an old one.
Baseline make_baseline(const std::vector<CaseResult>& cases, double default_tolerance,
                       const std::map<std::string, double>& tolerances);
nlohmann::json to_json(const Baseline& baseline);

/// Runs both checks. Throws SuiteInputError listing the cases found in only one of the two
/// (the files must cover the same cases).
GateReport run_gate(const Baseline& baseline, const std::vector<CaseResult>& results);

/// The failures as a Markdown-style text table (empty string when the gate passed).
std::string format_gate_failures(const GateReport& report);

}  // namespace cs::suites

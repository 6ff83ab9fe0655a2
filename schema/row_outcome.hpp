#pragma once
// What a CI test report says of one row (schema/row_verdict.hpp): passed, failed, errored or
// skipped, with the reasons. Computed by suites/ (suites/row_outcomes.hpp: after a run, or by
// the gate against a baseline), written by reports/ as JUnit XML and a Markdown summary
// (reports/junit_report.hpp). In memory only: results.json does not hold it.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "schema/case_axes.hpp"
#include "schema/name_table.hpp"

namespace cs::schema {

/// The JUnit outcome of a row.
enum class RowOutcomeKind : std::uint8_t {
  passed,   ///< every check made on the row held
  failed,   ///< a check failed (the gate: value drift, grade, convergence, divergence)
  error,    ///< a case of the row did not converge (or, by the gate, stopped converging)
  skipped,  ///< nothing was compared for the row (e.g. it has no graded value)
};
constexpr std::string_view axis_name(RowOutcomeKind) {
  return "row outcome";
}
constexpr AxisEntry entry(RowOutcomeKind v) {
  switch (v) {
    case RowOutcomeKind::passed:
      return {"passed", "", ""};
    case RowOutcomeKind::failed:
      return {"failed", "", ""};
    case RowOutcomeKind::error:
      return {"error", "", ""};
    case RowOutcomeKind::skipped:
      return {"skipped", "", ""};
  }
  return {};
}

/// One row as a CI test case.
struct RowOutcome {
  std::string row_id;         ///< the row's id, e.g. "H_p/Q4/LMP/ss/sigma_c": the test's name
  ProblemId problem{};        ///< the test's class (its JUnit testsuite)
  double wall_seconds = 0.0;  ///< summed over the row's cases (C, M, F, VF)
  RowOutcomeKind kind = RowOutcomeKind::passed;
  /// One line per failed check (failed), per case that did not converge (error), or the reason
  /// nothing was compared (skipped); empty when passed.
  std::vector<std::string> reasons;
  std::string summary;  ///< one line of what the row holds: grade, error, verdicts
  /// Compared with a baseline: how the row moved ("grade e -> g", "max drift 3.1e-05"); empty
  /// when its values are the baseline's bit for bit, or there was no baseline.
  std::string movement;
};

}  // namespace cs::schema

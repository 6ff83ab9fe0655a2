#pragma once
// Every row as a CI test case (schema/row_outcome.hpp), for the JUnit file and the Markdown
// summary of `run --junit` and `gate --junit`:
//   after a run: error when a case of the row did not converge (the run then exits 1),
//     skipped when the row has no grade and no convergence or divergence verdict, else passed;
//   by the gate: failed when a check of the gate failed on the row (its one-line reason per
//     check: value, baseline, tolerance), error when a case of the row stopped converging,
//     skipped when the baseline holds nothing the gate compares for the row, else passed.
// A testcase's time is the wall time of the row's cases (C, M, F, VF); cases are shared by the
// rows of their quantities, so the times of rows do not add up to the run's.

#include <vector>

#include "schema/baseline_file.hpp"
#include "schema/row_outcome.hpp"
#include "suites/case_result.hpp"
#include "suites/gate.hpp"
#include "suites/row_verdict.hpp"

namespace cs::suites {

using schema::RowOutcome;
using schema::RowOutcomeKind;

/// The rows of a run, in the rows' order.
std::vector<RowOutcome> run_row_outcomes(const std::vector<CaseResult>& cases,
                                         const std::vector<RowVerdict>& rows);

/// The rows of `results` as the gate judged them against `baseline` (`report` from run_gate on
/// the same two), in the results' row order.
std::vector<RowOutcome> gate_row_outcomes(const schema::Baseline& baseline,
                                          const GateReport& report,
                                          const std::vector<CaseResult>& results);

}  // namespace cs::suites

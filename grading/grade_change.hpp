#pragma once
// When a grade that changed between two runs of the same case says nothing of the code: the
// graded value moved by round-off across a band's bound of Eq. 46. The gate and the regression
// report both judge a grade change by this rule.

#include <optional>

#include "schema/row_verdict.hpp"

namespace cs::grading {

/// How far a value moved from its baseline a, relative: |b - a| / |a| (a = 0 counts as 1e-300,
/// so any move away from an exact zero is large).
double relative_drift(double a, double b);

/// A graded value and its percentage error (either may be missing).
struct GradedValue {
  std::optional<double> value, error;
};

/// The round-off a grade change is judged with: a quantity's gate tolerance, but never looser
/// than schema::kDefaultGateTolerance (a tolerance loosened for a quantity does not excuse a
/// grade that really dropped).
double round_off_tolerance(double quantity_tolerance);

/// Whether a grade change is round-off: the value moved by no more than `tolerance`
/// (relative_drift), and its errors lie in adjacent bands of Eq. 46, each within what that drift
/// moves an error of the bound b between them, 100 tolerance (1 + b / 100) points. A change of
/// the exact value (the error moves, the value does not), or one across more than a bound, is
/// not round-off. False when a value or an error is missing, or the grades are the same.
bool grade_change_is_round_off(const GradedValue& before, const GradedValue& after,
                               double tolerance);

/// The same for a row graded in two runs: both graded on the same mesh, whose value and error
/// are judged.
bool grade_change_is_round_off(const schema::RowVerdict& before, const schema::RowVerdict& after,
                               double tolerance);

}  // namespace cs::grading

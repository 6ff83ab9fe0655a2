#pragma once
// When a grade that changed between two runs of the same case says nothing of the code: the
// graded value moved by round-off and sat on a band's edge of Eq. 46. The gate and the
// regression report both judge a grade change by this rule.

#include <optional>

#include "schema/row_verdict.hpp"

namespace cs::grading {

/// How far a value moved from its baseline a, relative: |b - a| / |a| (a = 0 counts as 1e-300,
/// so any move away from an exact zero is large).
double relative_drift(double a, double b);

/// Whether a grade change is round-off: the graded value moved from a to b by no more than
/// `tolerance` (relative_drift <= tolerance), so its grade flipped on a band's edge. False when
/// either value is missing.
bool grade_change_is_round_off(std::optional<double> a, std::optional<double> b, double tolerance);

/// The same for a row graded in two runs: both graded on the same mesh, and that mesh's value
/// moved by no more than `tolerance`.
bool grade_change_is_round_off(const schema::RowVerdict& before, const schema::RowVerdict& after,
                               double tolerance);

}  // namespace cs::grading

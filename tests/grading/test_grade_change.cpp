// grading/grade_change: when a grade change between two runs is round-off.

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "grading/grade_change.hpp"
#include "schema/baseline_file.hpp"

namespace cs::grading {
namespace {

/// A value against the exact value 1 and its error.
GradedValue graded(double value, double exact = 1.0) {
  return {value, error_percent(value, exact)};
}

TEST(GradeChange, RelativeDriftIsMeasuredFromTheBaseline) {
  EXPECT_DOUBLE_EQ(relative_drift(2.0, 2.5), 0.25);
  EXPECT_DOUBLE_EQ(relative_drift(-2.0, -2.5), 0.25);
  EXPECT_GT(relative_drift(0.0, 1e-200), 1.0);  // any move away from an exact zero is large
  EXPECT_EQ(relative_drift(0.0, 0.0), 0.0);
}

// The round-off a grade change is judged with is the quantity's tolerance, never looser than the
// gate's default.
TEST(GradeChange, ARoundOffToleranceIsNeverLooserThanTheDefault) {
  EXPECT_EQ(round_off_tolerance(1e-2), schema::kDefaultGateTolerance);
  EXPECT_EQ(round_off_tolerance(1e-9), 1e-9);
}

// A value on the e/g bound of Eq. 46 that moves by 1e-9 flips its grade by round-off, and so on
// the g/s and s/u bounds, for errors of either sign; a move of 0.2 points, a missing value or
// error, or no change of grade is not round-off.
TEST(GradeChange, AFlipAcrossABoundByRoundOffIsRoundOff) {
  const GradedValue before = graded(1.0099999995), after = graded(1.0100000005);
  ASSERT_EQ(grade_of_error(*before.error), schema::Grade::e);
  ASSERT_EQ(grade_of_error(*after.error), schema::Grade::g);
  EXPECT_TRUE(grade_change_is_round_off(before, after, 1e-6));
  EXPECT_TRUE(grade_change_is_round_off(after, before, 1e-6));
  EXPECT_TRUE(grade_change_is_round_off(graded(0.9500000004), graded(0.9499999996), 1e-6));
  EXPECT_TRUE(grade_change_is_round_off(graded(1.0999999996), graded(1.1000000004), 1e-6));
  EXPECT_FALSE(grade_change_is_round_off(before, graded(1.012), 1e-6));
  EXPECT_FALSE(grade_change_is_round_off(before, {std::nullopt, after.error}, 1e-6));
  EXPECT_FALSE(grade_change_is_round_off({before.value, std::nullopt}, after, 1e-6));
  EXPECT_FALSE(grade_change_is_round_off(before, before, 1e-6));
}

// The band's edge is what the drift moves an error at the bound, 100 tolerance (1 + b/100)
// points: 1.01e-4 points at the e/g bound for 1e-6. An error 1.005e-4 below the bound and one
// 0.3e-4 above it (values 0.89e-6 apart) are round-off; an edge without the factor 1 + b/100
// (1e-4), or halved, would not cover the first. An error 1.2e-4 below the bound (the exact value
// moved, not the value) is not.
TEST(GradeChange, TheEdgeIsWhatTheToleranceMovesAnErrorAtTheBound) {
  const GradedValue below{1.0 + 0.01 - 0.6e-6, 1.0 - 1.005e-4};
  const GradedValue above{1.0 + 0.01 + 0.3e-6, 1.0 + 0.3e-4};
  EXPECT_TRUE(grade_change_is_round_off(below, above, 1e-6));
  const GradedValue below_far{1.0 + 0.01 - 0.6e-6, 1.0 - 1.2e-4};  // exact moved, not the value
  EXPECT_FALSE(grade_change_is_round_off(below_far, above, 1e-6));
  EXPECT_EQ(grade_upper_bound(schema::Grade::e), 1.0);
  EXPECT_EQ(grade_upper_bound(schema::Grade::g), 5.0);
  EXPECT_EQ(grade_upper_bound(schema::Grade::s), 10.0);
  EXPECT_TRUE(std::isinf(grade_upper_bound(schema::Grade::u)));
}

// The exact value changed (an oracle fixed): the value stays, its error jumps from e to u. No
// band's edge is involved, so it is no round-off; nor is a value that moves by round-off far
// from any bound while its grade changes with the exact value.
TEST(GradeChange, AChangeOfTheExactValueIsNoRoundOff) {
  EXPECT_FALSE(grade_change_is_round_off(graded(1.005, 1.0), graded(1.005, 0.8), 1e-6));
  EXPECT_FALSE(grade_change_is_round_off(graded(1.0099999995, 1.0), graded(1.0099999995, 0.999),
                                         1e-6));  // e to g, but by 0.1 points of exact value
}

// A row is judged on the mesh it is graded on, and only when both runs grade the same mesh.
TEST(GradeChange, ARowIsJudgedOnItsGradedMesh) {
  schema::RowVerdict before, after;
  before.values = {1.3, 1.2, 1.0099999995};
  after.values = {1.5, 1.4, 1.0100000005};  // C and M moved far; F by round-off
  for (std::size_t m = 0; m < 3; ++m) {
    before.errors[m] = error_percent(*before.values[m], 1.0);
    after.errors[m] = error_percent(*after.values[m], 1.0);
  }
  before.graded_mesh = after.graded_mesh = schema::MeshLevel::F;
  EXPECT_TRUE(grade_change_is_round_off(before, after, 1e-6));
  after.graded_mesh = schema::MeshLevel::M;
  EXPECT_FALSE(grade_change_is_round_off(before, after, 1e-6));
  before.graded_mesh.reset();
  after.graded_mesh.reset();
  EXPECT_FALSE(grade_change_is_round_off(before, after, 1e-6));
}

}  // namespace
}  // namespace cs::grading

// grading/grade_change: when a grade change between two runs is round-off.

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "grading/grade_change.hpp"

namespace cs::grading {
namespace {

TEST(GradeChange, RelativeDriftIsMeasuredFromTheBaseline) {
  EXPECT_DOUBLE_EQ(relative_drift(2.0, 2.5), 0.25);
  EXPECT_DOUBLE_EQ(relative_drift(-2.0, -2.5), 0.25);
  EXPECT_GT(relative_drift(0.0, 1e-200), 1.0);  // any move away from an exact zero is large
  EXPECT_EQ(relative_drift(0.0, 0.0), 0.0);
}

// A value on the e/g edge of Eq. 46 that moves by 1e-9 flips its grade by round-off; a move of
// 0.2 points does not count as round-off, nor does a missing value.
TEST(GradeChange, AFlipOnABandsEdgeIsRoundOff) {
  const double exact = 1.0, before = 1.0099999995, after = 1.0100000005;
  ASSERT_EQ(grade_of_error(error_percent(before, exact)), schema::Grade::e);
  ASSERT_EQ(grade_of_error(error_percent(after, exact)), schema::Grade::g);
  EXPECT_TRUE(grade_change_is_round_off(before, after, 1e-6));
  EXPECT_FALSE(grade_change_is_round_off(before, 1.012, 1e-6));
  EXPECT_FALSE(grade_change_is_round_off(before, std::nullopt, 1e-6));
  EXPECT_FALSE(grade_change_is_round_off(std::nullopt, after, 1e-6));
}

// A row is judged on the mesh it is graded on, and only when both runs grade the same mesh.
TEST(GradeChange, ARowIsJudgedOnItsGradedMesh) {
  schema::RowVerdict before, after;
  before.values = {1.3, 1.2, 1.0099999995};
  after.values = {1.5, 1.4, 1.0100000005};  // C and M moved far; F by round-off
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

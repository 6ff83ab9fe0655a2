// Requirement: the signed percentage error is relative to the exact value's magnitude, and
// Eq. 46 grades its magnitude with each boundary in the worse grade and NaN unsatisfactory.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"

namespace cs::grading {
namespace {

using schema::Grade;

TEST(Accuracy, Eq46BoundariesBelongToTheWorseGrade) {
  EXPECT_EQ(grade_of_error(0.0), Grade::e);
  EXPECT_EQ(grade_of_error(0.999), Grade::e);
  EXPECT_EQ(grade_of_error(-0.999), Grade::e);
  EXPECT_EQ(grade_of_error(1.0), Grade::g);
  EXPECT_EQ(grade_of_error(-4.999), Grade::g);
  EXPECT_EQ(grade_of_error(5.0), Grade::s);
  EXPECT_EQ(grade_of_error(9.999), Grade::s);
  EXPECT_EQ(grade_of_error(10.0), Grade::u);
  EXPECT_EQ(grade_of_error(-250.0), Grade::u);
  EXPECT_EQ(grade_of_error(std::numeric_limits<double>::quiet_NaN()), Grade::u);
  EXPECT_EQ(grade_of_error(std::numeric_limits<double>::infinity()), Grade::u);
}

TEST(Accuracy, ErrorPercentIsSignedAndRelativeToTheExactMagnitude) {
  // Binary-exact operands, so the results are exact.
  EXPECT_EQ(error_percent(1.25, 1.0), 25.0);
  EXPECT_EQ(error_percent(0.75, 1.0), -25.0);
  EXPECT_EQ(error_percent(-1.25, -1.0), -25.0);  // below a negative exact value: negative
  EXPECT_EQ(error_percent(3.0, 2.0), 50.0);
}

TEST(Accuracy, StudyTable3aValueGradesAsTheStudyGradesIt) {
  // Table 3a LMP/PLM fine mesh 1.0019 against 1: graded 'e' in Table 2a.
  EXPECT_EQ(grade_of_error(error_percent(1.0019, 1.0)), Grade::e);
  // Table 7a (4Q, ss, AL/PM) fine mesh 1.2737 against 4/pi: 'e' in Table 2a.
  EXPECT_EQ(grade_of_error(error_percent(1.2737, 4.0 / M_PI)), Grade::e);
}

}  // namespace
// Requirement: a grade's band width follows Eq. 46's bounds, checked against grade_of_error at
// both edges of each band.
TEST(Accuracy, GradeBandWidthsFollowEq46) {
  for (const Grade g : {Grade::e, Grade::g, Grade::s}) {
    double low = 0.0;
    while (grade_of_error(low) != g)
      low += 0.5;
    const double width = grade_band_width(g);
    EXPECT_EQ(grade_of_error(low + width - 1e-9), g);
    EXPECT_NE(grade_of_error(low + width), g);
  }
  EXPECT_TRUE(std::isinf(grade_band_width(Grade::u)));
}

// Requirement: a value read between two nodes lies anywhere in its error +- its resolution r;
// it settles a grade only when that whole interval falls in one band of Eq. 46, e.g. not the
// friction read that graded an option u.
TEST(Accuracy, AReadBetweenNodesSettlesAGradeOnlyWithinOneBand) {
  EXPECT_FALSE(read_settles_grade(10.49, 4.42));  // CM_p PM ss Q4 c/a: 6.07 % (s) to 14.9 % (u)
  EXPECT_FALSE(read_settles_grade(-10.49, 4.42));
  EXPECT_TRUE(read_settles_grade(20.0, 4.42));   // u either way
  EXPECT_FALSE(read_settles_grade(3.0, 4.42));   // within its resolution of zero
  EXPECT_FALSE(read_settles_grade(6.25, 6.25));  // an edge at a node: exactly half a node off
  EXPECT_TRUE(read_settles_grade(0.3, 0.2));
  EXPECT_FALSE(read_settles_grade(0.9, 0.2));  // 0.7 % (e) to 1.1 % (g)
  EXPECT_TRUE(read_settles_grade(12.0, 0.0));  // read at a point
  // The whole resolution on each side, not half of it nor twice it:
  EXPECT_FALSE(read_settles_grade(7.0, 2.5));  // 4.5 % (g) to 9.5 % (s); +-1.25 would stay s
  EXPECT_TRUE(read_settles_grade(7.5, 2.0));   // 5.5 % to 9.5 %, s; +-4 would reach g and u
}

// Requirement: a read's best reading is its |error| less its whole resolution, never below 0,
// graded by Eq. 46: the friction read +8.28 +- 2.21 % is at best s, +10.49 +- 4.42 % too; a read
// within its resolution of zero (an edge exactly half a node off) is at best e; a point is
// graded as it reads; NaN stays u.
TEST(Accuracy, AReadsBestReadingIsItsErrorLessItsResolution) {
  EXPECT_EQ(best_reading_grade(8.28, 2.21), Grade::s);
  EXPECT_EQ(best_reading_grade(-10.49, 4.42), Grade::s);
  EXPECT_EQ(best_reading_grade(15.0, 4.99), Grade::u);  // at best 10.01 %: still u
  EXPECT_EQ(best_reading_grade(15.0, 5.01), Grade::s);  // at best 9.99 %: s
  EXPECT_EQ(best_reading_grade(6.25, 6.25), Grade::e);
  EXPECT_EQ(best_reading_grade(3.0, 4.42), Grade::e);
  EXPECT_EQ(best_reading_grade(12.0, 0.0), Grade::u);
  EXPECT_EQ(best_reading_grade(NAN, 1.0), Grade::u);
}

// Requirement: a read is at least a grade when its worst reading is, not at all when its best
// reading is worse, and open otherwise; a point read is graded as it reads.
TEST(Accuracy, AReadIsAtLeastAGradeOnlyWhereEveryReadingAgrees) {
  EXPECT_EQ(read_at_least(2.0, 1.0, Grade::g), true);     // 1 % to 3 %
  EXPECT_EQ(read_at_least(-12.0, 4.0, Grade::g), false);  // 8 % at best: s
  EXPECT_EQ(read_at_least(6.25, 6.25, Grade::g), std::nullopt);
  EXPECT_EQ(read_at_least(4.5, 0.4, Grade::g), true);          // 4.9 % at worst
  EXPECT_EQ(read_at_least(4.5, 0.6, Grade::g), std::nullopt);  // 5.1 % at worst
  EXPECT_EQ(read_at_least(0.5, 0.0, Grade::e), true);
  EXPECT_EQ(read_at_least(1.5, 0.0, Grade::e), false);
}

// Requirement: two values coincide at the study's resolution, 0.01 % of the larger magnitude,
// pinned at the threshold on both sides, whatever the sign and the scale.
TEST(Accuracy, ValuesCoincideWithinAHundredthOfAPercent) {
  EXPECT_TRUE(values_coincide(1.0, 1.0 + 0.9e-4));
  EXPECT_FALSE(values_coincide(1.0, 1.0 + 1.1e-4));
  EXPECT_TRUE(values_coincide(-11.2424, -11.2424 * (1.0 + 0.9e-4)));
  EXPECT_FALSE(values_coincide(11.2424, 11.2424 * (1.0 + 1.1e-4)));
  EXPECT_FALSE(values_coincide(1e-3, -1e-3));
  EXPECT_TRUE(values_coincide(0.0, 0.0));
}

}  // namespace cs::grading

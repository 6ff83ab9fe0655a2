// Grading rules: Eq. 46 boundaries, the converging criterion, Eq. 47.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "schema/schema_error.hpp"

#include "suites/grading.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

TEST(Grading, Eq46BoundariesBelongToTheWorseGrade) {
  EXPECT_EQ(grade_from_error(0.0), Grade::e);
  EXPECT_EQ(grade_from_error(0.999), Grade::e);
  EXPECT_EQ(grade_from_error(1.0), Grade::g);
  EXPECT_EQ(grade_from_error(-4.999), Grade::g);
  EXPECT_EQ(grade_from_error(5.0), Grade::s);
  EXPECT_EQ(grade_from_error(9.999), Grade::s);
  EXPECT_EQ(grade_from_error(10.0), Grade::u);
  EXPECT_EQ(grade_from_error(-250.0), Grade::u);
  EXPECT_EQ(grade_from_error(std::numeric_limits<double>::quiet_NaN()), Grade::u);
}

TEST(Grading, ErrorPercentIsSignedAndRelativeToTheExactMagnitude) {
  // Binary-exact operands, so the results are exact.
  EXPECT_EQ(error_percent(1.25, 1.0), 25.0);
  EXPECT_EQ(error_percent(0.75, 1.0), -25.0);
  EXPECT_EQ(error_percent(-1.25, -1.0), -25.0);
  EXPECT_EQ(error_percent(3.0, 2.0), 50.0);
}

TEST(Grading, StudyTable7aValuesGradeAsTheStudyGradesThem) {
  // Table 7a (4Q, ss, AL/PM) fine mesh 1.2737 vs 4/pi: Table 2a grades H_p contact 'e, c'.
  const double exact = 4.0 / M_PI;
  const double c = error_percent(1.2628, exact), m = error_percent(1.2704, exact),
               f = error_percent(1.2737, exact);
  EXPECT_EQ(grade_from_error(f), Grade::e);
  EXPECT_TRUE(is_converging(c, m, f));
  // Table 3a LMP/PLM 1.0001, 1.0003, 1.0019: 'e' and not converging (Table 2a).
  EXPECT_EQ(grade_from_error(error_percent(1.0019, 1.0)), Grade::e);
  EXPECT_FALSE(is_converging(0.01, 0.03, 0.19));
}

TEST(Grading, ExactOnEveryMeshIsConverging) {
  EXPECT_TRUE(is_converging(1e-12, 3e-12, 2e-12));
  EXPECT_FALSE(is_converging(5.0, 5.0, 5.0));  // stuck at 5 %: not converging
  EXPECT_FALSE(is_converging(1.0, 2.0, 0.5));  // grows on M
  EXPECT_FALSE(is_converging(std::nan(""), 1.0, 0.5));
}

TEST(Grading, Eq47Divergence) {
  EXPECT_TRUE(is_diverging(1.0, 1.2, 1.5));   // increments grow: diverging
  EXPECT_FALSE(is_diverging(1.0, 1.5, 1.6));  // increments shrink: converging
}

TEST(Grading, GradeOrderAndNames) {
  EXPECT_TRUE(is_worse(Grade::u, Grade::s));
  EXPECT_FALSE(is_worse(Grade::e, Grade::g));
  for (Grade g : {Grade::e, Grade::g, Grade::s, Grade::u}) {
    EXPECT_EQ(schema::parse<Grade>(schema::to_string(g)), g);
  }
  EXPECT_THROW(schema::parse<Grade>("x"), schema::SchemaError);
}

}  // namespace
}  // namespace cs::suites

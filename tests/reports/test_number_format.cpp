// How the report prints its numbers (reports/tables/markdown_table.hpp): a signed error always
// carries its sign, a negative one the minus sign '−' (U+2212), never the hyphen, and an error
// below the study's 0.01 % resolution is printed in scientific notation, not as "0.00 %".

#include <gtest/gtest.h>

#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

// Requirement: a leading hyphen becomes the minus sign; anything else is left as it is.
TEST(NumberFormat, ALeadingHyphenBecomesTheMinusSign) {
  EXPECT_EQ(with_minus_sign("-0.05"), "−0.05");
  EXPECT_EQ(with_minus_sign("-1.2e-13 %"), "−1.2e-13 %");
  EXPECT_EQ(with_minus_sign("+0.05"), "+0.05");
  EXPECT_EQ(with_minus_sign("0.5-1"), "0.5-1");  // only a leading sign
  EXPECT_EQ(with_minus_sign(""), "");
}

// Requirement: errors are signed (positive with '+', negative with '−') with 2 decimals below
// 10 % and 1 above; below 0.01 % in magnitude they are not rounded to zero.
TEST(NumberFormat, ErrorsAreSignedAndNeverRoundedToZero) {
  EXPECT_EQ(format_error_resolved(0.278), "+0.28 %");
  EXPECT_EQ(format_error_resolved(-0.278), "−0.28 %");
  EXPECT_EQ(format_error_resolved(-52.26), "−52.3 %");
  EXPECT_EQ(format_error_resolved(3.3e-12), "+3.3e-12 %");
  EXPECT_EQ(format_error_resolved(-4.1e-13), "−4.1e-13 %");
  EXPECT_EQ(format_error_resolved(0.0), "+0.00 %");
  EXPECT_EQ(format_error_resolved(std::optional<double>()), kMissing);
}

}  // namespace
}  // namespace cs::reports

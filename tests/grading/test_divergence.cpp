// Requirement: Eq. 47 holds when the increments grow; the strict divergence verdict accepts a
// square-root singularity and rejects the study's false "diverging" rows (tensile and
// shrinking, decreasing, non-monotone) and growth far slower than a square root.

#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "grading/divergence.hpp"
#include "support/tolerance.hpp"

namespace cs::grading {
namespace {

using cs::testing::Near;

TEST(Divergence, Eq47) {
  EXPECT_TRUE(eq47_diverging(1.0, 1.2, 1.5));   // increments grow: diverging
  EXPECT_FALSE(eq47_diverging(1.0, 1.5, 1.6));  // increments shrink: converging
  EXPECT_FALSE(eq47_diverging(1.0, 1.5, 2.0));  // equal increments: not diverging
}

TEST(Divergence, StrictVerdictAcceptsASquareRootSingularityOnly) {
  const double s = 3.0;
  const auto sqrt_growth = divergence_verdict(s, s * std::sqrt(2.0), s * 2.0);
  EXPECT_TRUE(sqrt_growth.diverges);
  EXPECT_TRUE(sqrt_growth.monotone);
  EXPECT_TRUE(Near(*sqrt_growth.exponent, 0.5, {1e-12, 0}));  // machine precision
  // F_a Q4 MPC ss (tensile and shrinking), F_a Q8 MPC ss (decreasing), F_a Q8 LMP ss
  // (non-monotone): all pass Eq. 47, none diverges under the strict verdict.
  for (auto [c, m, f] : {std::array{-11.97, -12.02, -10.71}, std::array{73.55, 73.30, 72.94},
                         std::array{3.156, 2.690, 3.164}}) {
    const auto d = divergence_verdict(c, m, f);
    EXPECT_TRUE(d.eq47);
    EXPECT_FALSE(d.diverges);
  }
  EXPECT_FALSE(divergence_verdict(1.0, 1.01, 1.03).diverges);  // monotone but far too slow
  EXPECT_FALSE(divergence_verdict(1.0, 2.0, 4.0).diverges);    // alpha 1: too fast
}

TEST(Divergence, NoExponentAcrossASignChange) {
  const auto d = divergence_verdict(-1.0, 1.0, 2.0);
  EXPECT_FALSE(d.exponent.has_value());
  EXPECT_FALSE(d.monotone);
  EXPECT_FALSE(d.diverges);
}

}  // namespace
}  // namespace cs::grading

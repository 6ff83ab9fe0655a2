// Requirement: the observed order and the Richardson limit recover a sequence f = f* + C h^p
// exactly; GCI follows Roache's formula; no order is fitted to oscillatory, non-shrinking or
// round-off sequences; the strict divergence verdict accepts a square-root singularity and
// rejects the study's false "diverging" rows (tensile and shrinking, decreasing, non-monotone).

#include <gtest/gtest.h>

#include <cmath>

#include "suites/row_estimates.hpp"
#include "support/tolerance.hpp"

namespace cs::suites {
namespace {

using cs::testing::Near;

TEST(RowEstimates, RecoverOrderAndLimitOfAnExactPowerLaw) {
  for (double p : {1.0, 2.0, 2.7}) {
    const double exact = 1.2732, c = 0.3;
    auto f = [&](double h) { return exact + c * std::pow(h, p); };
    const auto e = error_estimate(f(1.0), f(0.5), f(0.25));
    ASSERT_TRUE(e.asymptotic);
    EXPECT_TRUE(Near(*e.observed_order, p, {1e-12, 0}));  // machine precision
    EXPECT_TRUE(Near(*e.richardson, exact, {1e-12, 0}));
    const double gci = 1.25 * std::abs((f(0.5) - f(0.25)) / f(0.25)) / (std::exp2(p) - 1) * 100;
    EXPECT_TRUE(Near(*e.gci_percent, gci, {1e-12, 0}));
    // The GCI bounds the true error of the fine value for this exact power law.
    EXPECT_GE(*e.gci_percent, std::abs(f(0.25) - exact) / exact * 100);
  }
}

TEST(RowEstimates, NoOrderForOscillatingShrinkingLessOrRoundOffSequences) {
  EXPECT_EQ(error_estimate(1.0, 1.1, 1.05).note, "oscillatory");
  EXPECT_EQ(error_estimate(1.0, 1.1, 1.3).note, "differences do not shrink");
  EXPECT_EQ(error_estimate(1.0, 1.0 + 1e-15, 1.0).note, "differences at round-off");
  const auto orders = pair_orders({{4.0, 1.0, 1e-12}});
  EXPECT_TRUE(Near(*orders[0], 2.0, {1e-12, 0}));
  EXPECT_FALSE(orders[1].has_value());  // 1e-12 % is round-off
}

TEST(RowEstimates, StrictDivergenceAcceptsASquareRootSingularityOnly) {
  const double s = 3.0;
  const auto sqrt_growth = divergence_verdict(s, s * std::sqrt(2.0), s * 2.0);
  EXPECT_TRUE(sqrt_growth.diverges);
  EXPECT_TRUE(Near(*sqrt_growth.exponent, 0.5, {1e-12, 0}));
  // F_a Q4 MPC ss (tensile and shrinking), F_a Q8 MPC ss (decreasing), F_a Q8 LMP ss
  // (non-monotone): all pass Eq. 47, none diverges under the strict verdict.
  for (auto [c, m, f] : {std::array{-11.97, -12.02, -10.71}, std::array{73.55, 73.30, 72.94},
                         std::array{3.156, 2.690, 3.164}}) {
    const auto d = divergence_verdict(c, m, f);
    EXPECT_TRUE(d.eq47);
    EXPECT_FALSE(d.diverges);
  }
  EXPECT_FALSE(divergence_verdict(1.0, 1.01, 1.03).diverges);  // monotone but far too slow
}

}  // namespace
}  // namespace cs::suites

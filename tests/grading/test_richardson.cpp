// Requirement: the observed order and the Richardson limit recover a sequence f = f* + C h^p
// exactly; GCI follows Roache's formula; no estimate is made of oscillatory, non-shrinking or
// round-off sequences.

#include <gtest/gtest.h>

#include <cmath>

#include "grading/richardson.hpp"
#include "support/tolerance.hpp"

namespace cs::grading {
namespace {

using cs::testing::Near;

TEST(Richardson, RecoverOrderAndLimitOfAnExactPowerLaw) {
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

TEST(Richardson, NoOrderForOscillatingShrinkingLessOrRoundOffSequences) {
  EXPECT_EQ(error_estimate(1.0, 1.1, 1.05).note, "oscillatory");
  EXPECT_EQ(error_estimate(1.0, 1.1, 1.3).note, "differences do not shrink");
  EXPECT_EQ(error_estimate(1.0, 1.0 + 1e-15, 1.0).note, "differences at round-off");
}

}  // namespace
}  // namespace cs::grading

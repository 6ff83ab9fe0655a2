// Requirement: the observed order and the Richardson limit recover a sequence f = f* + C h^p
// exactly; GCI follows Roache's formula; no estimate is made of oscillatory, non-shrinking or
// round-off sequences.

#include <gtest/gtest.h>

#include <array>
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

/// A row of sigma_c with exact value 10 and the given errors (%) on C, M, F, its Richardson
/// estimate made from the values.
schema::RowVerdict row_with_errors(std::array<double, 3> errors,
                                   schema::Quantity q = schema::Quantity::sigma_c) {
  schema::RowVerdict r;
  r.quantity = q;
  for (std::size_t m = 0; m < 3; ++m) {
    r.errors[m] = errors[m];
    r.values[m] = 10.0 * (1.0 + errors[m] / 100.0);
  }
  r.estimate = error_estimate(*r.values[0], *r.values[1], *r.values[2]);
  return r;
}

// Requirement: an estimate is used only where it can be trusted, each rule pinned at its
// threshold: an order of 0.4 is refused and 0.6 kept (the minimum is 0.5; at 0.19, like S(1) AL
// ns at extent 8, +0.35/+0.11/-0.13 %, the limit would lie 6.4 times the last change beyond F);
// C at +100 % is unresolved and +90 % is not; a patch test within 0.01 points on every mesh and
// a read between two nodes have none; a sequence converging to a limit other than the exact value
// (a finite block's bias) keeps its estimate whatever its errors' own orders.
TEST(TrustedEstimate, EachRuleAtItsThreshold) {
  // Differences 0.1 then 0.1 * 2^-p: errors 5, 4, 4 - 2^-p %.
  const auto of_order = [](double p) {
    return row_with_errors({5.0, 4.0, 4.0 - std::pow(2.0, -p)});
  };
  const schema::RowVerdict slow = of_order(0.4);
  ASSERT_TRUE(slow.estimate->asymptotic);  // by the differences alone
  EXPECT_EQ(trusted_estimate(slow).estimate, nullptr);
  EXPECT_EQ(trusted_estimate(slow).note, "order 0.40: the differences barely shrink");
  EXPECT_NE(trusted_estimate(of_order(0.6)).estimate, nullptr);
  const schema::RowVerdict unresolved_c = row_with_errors({100.0, 50.0, 25.0});
  EXPECT_EQ(trusted_estimate(unresolved_c).note, "pre-asymptotic (100 % on C or M: not resolved)");
  const schema::RowVerdict resolved_c = row_with_errors({90.0, 45.0, 22.5});
  ASSERT_NE(trusted_estimate(resolved_c).estimate, nullptr);
  EXPECT_NEAR(*trusted_estimate(resolved_c).estimate->richardson, 10.0, 1e-9);  // order 1
  EXPECT_EQ(trusted_estimate(row_with_errors({0.008, 0.004, 0.002})).estimate, nullptr);
  EXPECT_NE(trusted_estimate(row_with_errors({0.08, 0.04, 0.02})).estimate, nullptr);
  EXPECT_EQ(trusted_estimate(row_with_errors({8.0, 4.0, 2.0}, schema::Quantity::contact_half_width))
                .estimate,
            nullptr);
  // Values 10.5, 10.3, 10.2 converge (order 1) to 10.1, 1 % above the exact 10.
  const schema::RowVerdict biased_row = row_with_errors({5.0, 3.0, 2.0});  // the estimate's row
  const TrustedEstimate biased = trusted_estimate(biased_row);
  ASSERT_NE(biased.estimate, nullptr);
  EXPECT_NEAR(*biased.estimate->richardson, 10.1, 1e-9);
  EXPECT_EQ(trusted_estimate(schema::RowVerdict{}).estimate, nullptr);  // no estimate at all
  // Settled within the study's 0.01 points on both pairs (P_a Q8 AL ns, a +0.71 % bias whose
  // changes are 6e-6 and 5e-7 points): refused, however regular its ratios look; one pair beyond
  // 0.01 points keeps it.
  const TrustedEstimate settled =
      trusted_estimate(row_with_errors({0.7097934, 0.7097994, 0.7097999}));
  EXPECT_EQ(settled.estimate, nullptr);
  EXPECT_EQ(settled.note, "settled within the study's resolution: nothing to extrapolate");
  EXPECT_NE(trusted_estimate(row_with_errors({0.76, 0.73, 0.71})).estimate, nullptr);
  // A last change within the resolution (0.005 points) makes the order noise: refused, even
  // though C -> M moves 0.03 points.
  const TrustedEstimate last_at_noise = trusted_estimate(row_with_errors({0.76, 0.73, 0.725}));
  EXPECT_EQ(last_at_noise.estimate, nullptr);
  EXPECT_EQ(last_at_noise.note, "M to F within the study's resolution: the order would be noise");
  // Exactly at the resolution (0.73 -> 0.72 %, 0.01 points but for the last digits): refused.
  EXPECT_EQ(trusted_estimate(row_with_errors({0.76, 0.73, 0.72})).estimate, nullptr);
  // An order beyond the recovered stresses' reach plus one: 3.5 is refused on Q4 (at most 3),
  // kept on Q8 (at most 4).
  schema::RowVerdict steep = of_order(3.5);
  EXPECT_EQ(trusted_estimate(steep).estimate, nullptr);
  EXPECT_EQ(trusted_estimate(steep).note.rfind("order 3.50: above 3,", 0), 0u)
      << trusted_estimate(steep).note;
  steep.spec.element = schema::Element::Q8;
  EXPECT_NE(trusted_estimate(steep).estimate, nullptr);
  EXPECT_NE(trusted_estimate(of_order(2.9)).estimate, nullptr);
}

// Requirement: the GCI band holds the exact value when |f_F - exact| / |f_F| <= GCI.
TEST(Richardson, GciBandTest) {
  schema::RowVerdict r;
  r.values = {1.3, 1.28, 1.275};
  r.estimate = schema::ErrorEstimate{true, 2.0, 1.2733, 0.2, ""};
  EXPECT_TRUE(*gci_bounds_error(r, 1.2732));   // 0.14 % <= 0.2 %
  EXPECT_FALSE(*gci_bounds_error(r, 1.2700));  // 0.39 % > 0.2 %
  r.estimate.reset();
  EXPECT_FALSE(gci_bounds_error(r, 1.2732).has_value());
}

}  // namespace
}  // namespace cs::grading

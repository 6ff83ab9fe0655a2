// Flat punches with sharp corners: Sadowsky (Eq. 39) and Harding-Sneddon (Eq. 45) as printed,
// the plane punch's face kept flat, and the unbounded edge stress (the study's "-> infinity").

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "oracles/flat_punch.hpp"
#include "oracles/invalid_input.hpp"
#include "oracles/quadrature.hpp"
#include "support/tolerance.hpp"

namespace cs::oracles {
namespace {

using cs::testing::Near;
using std::numbers::pi;

constexpr cs::testing::Tolerance kRounding{.rel = 1e-14};

TEST(FlatPunch, SadowskyIsEq39AsPrinted) {
  const SadowskyPunch punch{.a = 2.0, .P = 6.0};
  const double p = sadowsky_mean_pressure(punch);
  EXPECT_TRUE(Near(p, 1.5, kRounding));
  for (const double x : {-1.9, -0.5, 0.0, 1.0, 1.999}) {
    const double eq39 = 2.0 * p * punch.a / (pi * std::sqrt(punch.a * punch.a - x * x));
    EXPECT_TRUE(Near(sadowsky_pressure(punch, x), eq39, {.rel = 1e-12})) << x;
  }
  EXPECT_TRUE(Near(sadowsky_pressure(punch, 0.0) / p, 2.0 / pi, kRounding));
  EXPECT_EQ(sadowsky_pressure(punch, 2.5), 0.0);
  EXPECT_EQ(sadowsky_pressure(punch, -2.0000001), 0.0);
}

TEST(FlatPunch, HardingSneddonIsEq45AsPrinted) {
  const HardingSneddonPunch punch{.a = 0.5, .P = 3.0};
  const double p = harding_sneddon_mean_pressure(punch);
  EXPECT_TRUE(Near(p, 3.0 / (pi * 0.25), kRounding));
  for (const double r : {0.0, 0.1, 0.3, 0.4999}) {
    const double eq45 = punch.a / (2.0 * std::sqrt(punch.a * punch.a - r * r)) * p;
    EXPECT_TRUE(Near(harding_sneddon_pressure(punch, r), eq45, {.rel = 1e-12})) << r;
  }
  EXPECT_TRUE(Near(harding_sneddon_pressure(punch, 0.0) / p, 0.5, kRounding));
  EXPECT_EQ(harding_sneddon_pressure(punch, 0.6), 0.0);
}

TEST(FlatPunch, SadowskyPressureKeepsThePunchFaceFlat) {
  // Plane-strain surface slope dw/dx ~ PV int p(s) / (s - x) ds must vanish under a flat
  // punch (Eq. 38: w = delta).
  const SadowskyPunch punch{.a = 1.5, .P = 4.0};
  for (const double x : {-1.2, -0.3, 0.2, 0.7, 1.4}) {
    const auto pv = integrate_cauchy_principal_value(
        [&](double s) { return sadowsky_pressure(punch, s); }, -punch.a, punch.a, x,
        {.abs = 1e-10 * punch.P / punch.a, .rel = 1e-10});
    // QAGS reaches ~1e-10 next to the inverse-square-root ends: 1e-8 of P/a.
    EXPECT_TRUE(Near(pv.value, 0.0, {.abs = 1e-8 * punch.P / punch.a})) << x;
  }
}

TEST(FlatPunch, EdgeStressIsUnbounded) {
  // The study's normalized edge stress -> infinity: the oracle refuses the edge itself and
  // grows as (a - x)^(-1/2) towards it.
  const SadowskyPunch plane{.a = 1.0, .P = 2.0};
  const HardingSneddonPunch axi{.a = 1.0, .P = 2.0};
  EXPECT_THROW((void)sadowsky_pressure(plane, 1.0), InvalidInput);
  EXPECT_THROW((void)sadowsky_pressure(plane, -1.0), InvalidInput);
  EXPECT_THROW((void)harding_sneddon_pressure(axi, 1.0), InvalidInput);
  for (const double gap : {1e-4, 1e-8}) {
    // Quartering the gap doubles the pressure (to O(gap)).
    const double ratio_plane =
        sadowsky_pressure(plane, 1.0 - gap / 4.0) / sadowsky_pressure(plane, 1.0 - gap);
    const double ratio_axi =
        harding_sneddon_pressure(axi, 1.0 - gap / 4.0) / harding_sneddon_pressure(axi, 1.0 - gap);
    EXPECT_TRUE(Near(ratio_plane, 2.0, {.rel = gap}));
    EXPECT_TRUE(Near(ratio_axi, 2.0, {.rel = gap}));
  }
}

}  // namespace
}  // namespace cs::oracles

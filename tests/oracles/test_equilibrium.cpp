// Global equilibrium: every contact pressure integrates to its load, and every interior field
// carries the load across a plane below the surface. Integrals by GSL adaptive quadrature,
// treating the square-root and inverse-square-root contact edges and Steuermann's log kinks
// at x = +-b as the difficult points they are.

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "oracles/boussinesq.hpp"
#include "oracles/flamant.hpp"
#include "oracles/flat_punch.hpp"
#include "oracles/hertz_axi.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/quadrature.hpp"
#include "oracles/steuermann.hpp"
#include "oracles/strip_load.hpp"
#include "support/tolerance.hpp"

namespace cs::oracles {
namespace {

using cs::testing::Near;
using std::numbers::pi;

// The bar for resultants: 1e-10, ten times looser than the requested quadrature
// tolerance, well above rounding of the pressure (1e-12 for Steuermann, see steuermann.hpp).
constexpr cs::testing::Tolerance kResultant{.rel = 1e-10};
constexpr QuadratureTolerance kQuad{.abs = 0.0, .rel = 1e-12};

TEST(Equilibrium, HertzPlanePressureIntegratesToTheLoad) {
  for (const double P : {1e-3, 1.0, 250.0}) {
    const HertzPlaneContact contact = hertz_plane_contact({.R = 7.0, .E = 2e5, .nu = 0.3, .P = P});
    const double a = contact.contact_half_width_a;
    const auto resultant =
        integrate([&](double x) { return hertz_plane_pressure(contact, x); }, -a, a, kQuad);
    EXPECT_TRUE(Near(resultant.value, P, kResultant)) << "P = " << P;
  }
}

TEST(Equilibrium, HertzAxiPressureIntegratesToTheLoad) {
  for (const double P : {1e-3, 1.0, 250.0}) {
    const HertzAxiContact contact = hertz_axi_contact({.R = 7.0, .E = 2e5, .nu = 0.3, .P = P});
    const double a = contact.contact_radius_a;
    const auto resultant = integrate(
        [&](double r) { return hertz_axi_pressure(contact, r) * 2.0 * pi * r; }, 0.0, a, kQuad);
    EXPECT_TRUE(Near(resultant.value, P, kResultant)) << "P = " << P;
  }
}

TEST(Equilibrium, SadowskyPressureIntegratesToTheLoad) {
  // QAGS on the raw pressure: its inverse-square-root ends are integrable singularities.
  const SadowskyPunch punch{.a = 2.5, .P = 3.0};
  const auto resultant =
      integrate([&](double x) { return sadowsky_pressure(punch, x); }, -punch.a, punch.a, kQuad);
  EXPECT_TRUE(Near(resultant.value, punch.P, kResultant));
  // QAWS with the end weights (a + x)^(-1/2) (a - x)^(-1/2) integrated exactly: the regular
  // part p(x) (a^2 - x^2)^(1/2) is P / pi, a check of the oracle's prefactor alone. QAWS
  // samples the end points, where the pressure is unbounded: take the limit from inside.
  const auto weighted = integrate_algebraic_ends(
      [&](double x) {
        const double inside =
            std::clamp(x, std::nextafter(-punch.a, 0.0), std::nextafter(punch.a, 0.0));
        return sadowsky_pressure(punch, inside) *
               std::sqrt((punch.a - inside) * (punch.a + inside));
      },
      -punch.a, punch.a, -0.5, -0.5, kQuad);
  EXPECT_TRUE(Near(weighted.value, punch.P, kResultant));
}

TEST(Equilibrium, HardingSneddonPressureIntegratesToTheLoad) {
  const HardingSneddonPunch punch{.a = 0.4, .P = 12.0};
  const auto resultant =
      integrate([&](double r) { return harding_sneddon_pressure(punch, r) * 2.0 * pi * r; }, 0.0,
                punch.a, kQuad);
  EXPECT_TRUE(Near(resultant.value, punch.P, kResultant));
  const auto weighted = integrate_algebraic_ends(
      [&](double r) {
        const double inside = std::min(r, std::nextafter(punch.a, 0.0));
        return harding_sneddon_pressure(punch, inside) * 2.0 * pi * inside *
               std::sqrt(punch.a - inside);
      },
      0.0, punch.a, 0.0, -0.5, kQuad);
  EXPECT_TRUE(Near(weighted.value, punch.P, kResultant));
}

TEST(Equilibrium, SteuermannPressureIntegratesToTheLoad) {
  // The study's three punches, with and without (1 - nu^2), and a heavier and a lighter load.
  for (const Eq32Factor factor : {Eq32Factor::kWithOneMinusNu2, Eq32Factor::kWithoutOneMinusNu2}) {
    for (const double re_over_b : {1.0, 1.0 / 3.0, 1.0 / 7.0}) {
      for (const double p_over_E : {1e-4, 1e-3, 3e-3}) {
        const SteuermannPunch punch = steuermann_study_punch({.b = 2.0,
                                                              .r_e = 2.0 * re_over_b,
                                                              .E = 7e4,
                                                              .nu = 0.25,
                                                              .p_over_E = p_over_E,
                                                              .eq32_factor = factor});
        const SteuermannContact contact = steuermann_contact(punch);
        const double a = contact.contact_half_width_a;
        // Difficult points: the log kink at x = b and the square-root edge at x = a.
        const std::array<double, 3> points{0.0, punch.b, a};
        const auto half = integrate_with_breakpoints(
            [&](double x) { return steuermann_pressure(contact, x); }, points, kQuad);
        EXPECT_TRUE(Near(2.0 * half.value, punch.P, kResultant))
            << to_string(factor) << ", r_e/b = " << re_over_b << ", p/E = " << p_over_E;
      }
    }
  }
}

TEST(Equilibrium, FlamantFieldCarriesTheLineLoadAcrossEveryDepth) {
  const FlamantLoad load{.P = 3.5};
  for (const double z : {0.01, 1.0, 40.0}) {
    const auto half = integrate_to_infinity(
        [&](double x) {
          return flamant_stress(load, {x, z}).sigma_z;
        },
        0.0, kQuad);
    EXPECT_TRUE(Near(2.0 * half.value, -load.P, kResultant)) << "z = " << z;
  }
}

TEST(Equilibrium, McEwenAndStripFieldsCarryTheirLoadsAcrossEveryDepth) {
  const McEwenLoad hertz{.a = 0.5, .p = 3.0};
  const StripLoad strip{.a = 0.5, .p = 3.0};
  const double load = 2.0 * 0.5 * 3.0;  // P = 2 a p for both
  for (const double z : {0.05, 0.5, 4.0}) {
    // Split at the contact edge, where the near-surface fields change fastest.
    const auto mcewen_near = integrate(
        [&](double x) {
          return mcewen_stress(hertz, {x, z}).sigma_z;
        },
        0.0, 2.0, kQuad);
    const auto mcewen_far = integrate_to_infinity(
        [&](double x) {
          return mcewen_stress(hertz, {x, z}).sigma_z;
        },
        2.0, kQuad);
    EXPECT_TRUE(Near(2.0 * (mcewen_near.value + mcewen_far.value), -load, kResultant))
        << "McEwen, z = " << z;
    const auto strip_near = integrate(
        [&](double x) {
          return strip_load_stress(strip, {x, z}).sigma_z;
        },
        0.0, 2.0, kQuad);
    const auto strip_far = integrate_to_infinity(
        [&](double x) {
          return strip_load_stress(strip, {x, z}).sigma_z;
        },
        2.0, kQuad);
    EXPECT_TRUE(Near(2.0 * (strip_near.value + strip_far.value), -load, kResultant))
        << "strip, z = " << z;
  }
}

TEST(Equilibrium, BoussinesqFieldCarriesThePointLoadAcrossEveryDepth) {
  for (const double nu : {0.0, 0.25, 0.49}) {
    const BoussinesqLoad load{.P = 6.0, .nu = nu};
    for (const double z : {0.02, 1.0, 30.0}) {
      const auto resultant = integrate_to_infinity(
          [&](double r) {
            return boussinesq_stress(load, {r, z}).sigma_z * 2.0 * pi * r;
          },
          0.0, kQuad);
      EXPECT_TRUE(Near(resultant.value, -load.P, kResultant)) << "nu = " << nu << ", z = " << z;
    }
  }
}

}  // namespace
}  // namespace cs::oracles

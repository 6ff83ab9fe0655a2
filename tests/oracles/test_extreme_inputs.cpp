// Oracles at extreme but legal inputs (issue 16, item 7): each answers to full precision across
// its documented domain, refuses just outside it with a message naming the bound, and is
// scale-invariant (lengths and loads scaled by 1e+-300 give the same normalized answers).
// Steuermann's references are Eqs. 31-32 as printed in 250-digit arithmetic
// (steuermann_reference.py, mpmath).

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "oracles/boussinesq.hpp"
#include "oracles/flamant.hpp"
#include "oracles/flat_punch.hpp"
#include "oracles/invalid_input.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/quadrature.hpp"
#include "oracles/steuermann.hpp"
#include "oracles/strip_load.hpp"
#include "support/tolerance.hpp"

namespace cs::oracles {
namespace {

using cs::testing::Near;
using std::numbers::pi;

constexpr double kMinNormal = std::numeric_limits<double>::min();
constexpr double kMax = std::numeric_limits<double>::max();

/// Expects InvalidInput whose one-line message contains `mention`.
template <typename Call>
void expect_refusal(Call call, const std::string& mention, const std::string& label) {
  try {
    call();
    ADD_FAILURE() << label << ": no exception";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(mention), std::string::npos) << label << ": " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << label << ": " << what;
  }
}

// ---------------------------------------------------------------------------------------------
// Steuermann

struct SteuermannReference {
  SteuermannPunch punch;
  double a, phi0, u, peak, x_peak, p_half_b;  // 250-digit values, rounded to 17 digits
};

// steuermann_reference.py: light loads (u = 1.4e-8, 1.4e-4, 3.6e-64), the study's load, and
// heavy loads on a nearly cylindrical punch (phi0 = 9e-17, 9e-21).
const SteuermannReference kReferences[] = {
    {{1, 1, 1e-24, 1, 0.25},
     1.0000000000000001,
     1.5707963126793562,
     1.4115540433215426e-8,
     4.0579697239821863e-17,
     1.0,
     3.6755259694786131e-25},
    {{1, 1, 1e-12, 1, 0.25},
     1.0000000099624241,
     1.5706551713913145,
     0.00014115540358215428,
     4.0579697192307526e-9,
     1.0000000030403671,
     3.6755259401848952e-13},
    {{1, 1, 4e-3, 1, 0.25},
     1.0249592374565177,
     1.3496587091154477,
     0.22113761767944895,
     0.010195606977143299,
     1.0075951539868837,
     0.0014415690108532395},
    {{1, 1e40, 1, 1, 0.25},
     1.0925484305920791e+20,
     9.1529123286376898e-21,
     1.5707963267948966,
     5.826924963157755e-21,
     8339891685.0525561,
     5.826924963157755e-21},
    {{1, 1e32, 1, 1, 0.25},
     10925484305920792.0,
     9.1529123286376892e-17,
     1.5707963267948965,
     5.8269249631577485e-17,
     83398916.850525566,
     5.8269249631577422e-17},
    {{2.5, 1e-60, 1e-130, 1, 0.25},
     2.5,
     1.5707963267948966,
     3.5568933044900629e-64,
     6.4416254087044274e-68,
     2.5,
     1.4702103877914456e-131},
};

TEST(ExtremeInputs, SteuermannMatchesEq31InHighPrecisionFromLightToHeavyLoads) {
  // Requirement: the pressure, its peak and Eq. 32's root keep their digits where the printed
  // bracket cancels from O(u) to O(u^3) (light loads) and where phi0 -> 0 (r_e >> b).
  // Tolerance 1e-13: the regrouped bracket is accurate to a few ulps; Brent's root to 4 eps
  // (observed: 1e-15 and better).
  constexpr cs::testing::Tolerance kDigits{.rel = 1e-13};
  for (const SteuermannReference& ref : kReferences) {
    const SteuermannContact c = steuermann_contact(ref.punch);
    const SteuermannPeak peak = steuermann_peak(c);
    const std::string label =
        "r_e = " + format_value(ref.punch.r_e) + ", P = " + format_value(ref.punch.P);
    EXPECT_TRUE(Near(c.contact_half_width_a, ref.a, kDigits)) << label;
    EXPECT_TRUE(Near(c.phi0, ref.phi0, kDigits)) << label;
    EXPECT_TRUE(Near(c.half_pi_minus_phi0, ref.u, kDigits)) << label;
    EXPECT_TRUE(Near(peak.peak_pressure, ref.peak, kDigits)) << label;
    EXPECT_TRUE(Near(peak.x_peak, ref.x_peak, kDigits)) << label;
    EXPECT_TRUE(Near(steuermann_pressure(c, 0.5 * ref.punch.b), ref.p_half_b, kDigits)) << label;
  }
}

TEST(ExtremeInputs, SteuermannIssueCasesAnswerTheHertzAndSadowskyLimits) {
  // The issue's probes: load 1e-24 gave peak 0; r_e = 1e32 and 1e33 gave the same a; r_e = 1e40
  // was refused. For r_e >> b the punch is a cylinder: a -> Hertz's (4 r_e (1 - nu^2) P /
  // (pi E))^(1/2) and the peak -> 2P / (pi a), to O(phi0) (1e-16 here: 1e-12 covers rounding).
  const SteuermannPeak light = steuermann_peak(steuermann_contact({1, 1, 1e-24, 1, 0.25}));
  EXPECT_GT(light.peak_pressure, 0.0);
  for (const double r_e : {1e32, 1e33, 1e40}) {
    const SteuermannPunch punch{1, r_e, 1, 1, 0.25};
    const SteuermannContact c = steuermann_contact(punch);
    const double hertz_a = std::sqrt(4.0 * r_e * (1.0 - 0.25 * 0.25) / pi);
    EXPECT_TRUE(Near(c.contact_half_width_a, hertz_a, {.rel = 1e-12})) << r_e;
    EXPECT_TRUE(Near(steuermann_peak(c).peak_pressure, 2.0 / (pi * hertz_a), {.rel = 1e-12}))
        << r_e;
  }
  // ... and light loads tend to Sadowsky's P / (pi (b^2 - x^2)^(1/2)) on the flat face, to
  // O(u^2) (u = 1.4e-8: 1e-15).
  const SteuermannContact c = steuermann_contact({1, 1, 1e-24, 1, 0.25});
  for (const double x : {0.0, 0.5, 0.9}) {
    EXPECT_TRUE(Near(steuermann_pressure(c, x), sadowsky_pressure({1.0, 1e-24}, x), {.rel = 1e-14}))
        << x;
  }
}

TEST(ExtremeInputs, SteuermannIsScaleInvariant) {
  // b, r_e, P scaled by s, E fixed: a scales by s, the pressure not at all (P/b fixed).
  const SteuermannPunch unit{1.0, 0.5, 4e-3, 1.0, 0.25};
  const SteuermannContact c1 = steuermann_contact(unit);
  const SteuermannPeak p1 = steuermann_peak(c1);
  for (const double s : {1e-300, 1e-150, 1e150, 1e300}) {
    const SteuermannContact cs =
        steuermann_contact({unit.b * s, unit.r_e * s, unit.P * s, unit.E, unit.nu});
    const SteuermannPeak ps = steuermann_peak(cs);
    // Rounding of the scaled inputs (s is not a power of two): 1e-14.
    EXPECT_TRUE(Near(cs.contact_half_width_a / s, c1.contact_half_width_a, {.rel = 1e-14})) << s;
    EXPECT_TRUE(Near(ps.peak_pressure, p1.peak_pressure, {.rel = 1e-14})) << s;
    EXPECT_TRUE(Near(ps.x_peak / s, p1.x_peak, {.rel = 1e-14})) << s;
    EXPECT_TRUE(
        Near(steuermann_pressure(cs, 0.3 * s), steuermann_pressure(c1, 0.3), {.rel = 1e-14}))
        << s;
  }
}

TEST(ExtremeInputs, SteuermannDomainEdgesBothSides) {
  // r_e / b in [1e-100, 1e100].
  EXPECT_NO_THROW((void)steuermann_peak(steuermann_contact({1.0, 1e-100, 1e-160, 1.0, 0.25})));
  expect_refusal(
      [] {
        (void)steuermann_contact({1.0, 0.99e-100, 1e-160, 1.0, 0.25});
      },
      "r_e/b", "r_e/b below 1e-100");
  EXPECT_NO_THROW((void)steuermann_peak(steuermann_contact({1.0, 1e100, 1.0, 1.0, 0.25})));
  expect_refusal(
      [] {
        (void)steuermann_contact({1.0, 1.01e100, 1.0, 1.0, 0.25});
      },
      "r_e/b", "r_e/b above 1e100");
  // lambda = 2 (1 - nu^2) (r_e/b) (P/b) / E >= 1e-300: at nu = 0, r_e = b, E = 1, P = 0.5e-300.
  const SteuermannContact lightest = steuermann_contact({1.0, 1.0, 0.5e-300, 1.0, 0.0});
  EXPECT_TRUE(Near(steuermann_pressure(lightest, 0.0), 0.5e-300 / pi, {.rel = 1e-15}));
  EXPECT_GT(steuermann_peak(lightest).peak_pressure, steuermann_pressure(lightest, 0.0));
  expect_refusal(
      [] {
        (void)steuermann_contact({1.0, 1.0, 0.49e-300, 1.0, 0.0});
      },
      "too light", "lambda below 1e-300");
  // The largest load: a = b + r_e, and just above it a refusal naming the rounded edges.
  const SteuermannPunch heavy{1.0, 1e40, 1.0, 1.0, 0.25};
  const double max_load = steuermann_max_load(heavy);
  const SteuermannContact at_max = steuermann_contact({1.0, 1e40, max_load, 1.0, 0.25});
  EXPECT_TRUE(Near(at_max.contact_half_width_a, 1.0 + 1e40, {.rel = 1e-12}));
  expect_refusal(
      [&] {
        (void)steuermann_contact({1.0, 1e40, max_load * 1.000001, 1.0, 0.25});
      },
      "rounded edges", "overload");
  // A load whose parameter overflows.
  expect_refusal(
      [] {
        (void)steuermann_contact({1e-300, 1e-300, 1e300, 1.0, 0.25});
      },
      "floating-point range", "lambda overflows");
}

TEST(ExtremeInputs, SteuermannPressureIntegratesToTheLoadAtLightAndHeavyLoads) {
  // Equilibrium where the old form lost its digits: u = 1e-3 (rounded edges 5e-7 b wide) and
  // phi0 = 1e-6 (a = 1e6 b). Quadrature to 1e-12 around the kink at b and the edge at a: 1e-10.
  const QuadratureTolerance tol{.abs = 0.0, .rel = 1e-12};
  for (const SteuermannPunch& punch :
       {SteuermannPunch{1.0, 1.0, 1.6e-9, 1.0, 0.25}, SteuermannPunch{1.0, 1e12, 1.0, 1.0, 0.25}}) {
    const SteuermannContact c = steuermann_contact(punch);
    const std::array<double, 3> points{0.0, punch.b, c.contact_half_width_a};
    const auto half = integrate_with_breakpoints(
        [&](double x) { return steuermann_pressure(c, x); }, points, tol);
    EXPECT_TRUE(Near(2.0 * half.value, punch.P, {.rel = 1e-10}))
        << "u = " << c.half_pi_minus_phi0 << ", phi0 = " << c.phi0;
  }
}

// ---------------------------------------------------------------------------------------------
// Flat punches

TEST(ExtremeInputs, FlatPunchesAnswerAtEveryScaleAndRefuseOutOfRange) {
  // The issue's probes: a = 1e300 gave 0, a = 1e-300 was refused.
  EXPECT_TRUE(Near(sadowsky_pressure({1e300, 1.0}, 0.0), 1.0 / (pi * 1e300), {.rel = 1e-15}));
  EXPECT_TRUE(Near(sadowsky_pressure({1e-300, 1.0}, 0.0), 1.0 / (pi * 1e-300), {.rel = 1e-15}));
  EXPECT_TRUE(Near(sadowsky_mean_pressure({1e-300, 1.0}), 0.5e300, {.rel = 1e-15}));
  EXPECT_TRUE(
      Near(harding_sneddon_pressure({1e-300, 1e-300}, 0.0), 1e300 / (2.0 * pi), {.rel = 1e-15}));
  EXPECT_TRUE(Near(harding_sneddon_pressure({1e300, 1e300}, 0.5e300),
                   1e-300 / (2.0 * pi * std::sqrt(0.75)), {.rel = 1e-15}));
  // Scale invariance: p(s a, s P, s x) = p(a, P, x), at the edge too (s a power of two, so that
  // x s is exact: next to the edge the pressure amplifies any rounding of x by a / (a - x)).
  for (const double s : {std::ldexp(1.0, -996), std::ldexp(1.0, 996)}) {
    for (const double x : {0.0, 0.7, 1.0 - 1e-12}) {
      EXPECT_TRUE(Near(sadowsky_pressure({2.0 * s, 3.0 * s}, 2.0 * x * s),
                       sadowsky_pressure({2.0, 3.0}, 2.0 * x), {.rel = 1e-14}))
          << s << ", " << x;
    }
  }
  // The pressure scale P/a (P/a^2) must be a normal double: both sides of each bound.
  EXPECT_TRUE(Near(sadowsky_pressure({1.0, kMinNormal}, 0.0), kMinNormal / pi, {.rel = 1e-15}));
  expect_refusal(
      [] {
        (void)sadowsky_pressure({2.0, kMinNormal}, 0.0);
      },
      "floating-point range", "P/a subnormal");
  EXPECT_TRUE(Near(sadowsky_pressure({1.0, kMax}, 0.0), kMax / pi, {.rel = 1e-15}));
  expect_refusal(
      [] {
        (void)sadowsky_pressure({0.5, kMax}, 0.0);
      },
      "floating-point range", "P/a overflows");
  expect_refusal(
      [] {
        (void)sadowsky_pressure({1.0, kMax}, 1.0 - 1e-15);
      },
      "floating-point range", "pressure overflows next to the edge");
  EXPECT_NO_THROW((void)harding_sneddon_pressure({1e-154, 1e-308}, 0.0));
  expect_refusal(
      [] {
        (void)harding_sneddon_pressure({1e-300, 1.0}, 0.0);
      },
      "floating-point range", "P/a^2 overflows");
  expect_refusal(
      [] {
        (void)harding_sneddon_pressure({1e300, 1.0}, 0.0);
      },
      "floating-point range", "P/a^2 underflows");
}

// ---------------------------------------------------------------------------------------------
// Interior fields far away and close to their load

TEST(ExtremeInputs, BoussinesqFarPointsAnswerAndScale) {
  // sigma(s r, s z; s^2 P) = sigma(r, z; P): s = 1e150 is exact to rounding of the inputs.
  const AxiStress near = boussinesq_stress({3.0, 0.3}, {1.0, 2.0});
  for (const double s : {1e-100, 1e100, 1e150}) {
    const AxiStress far = boussinesq_stress({3.0 * s * s, 0.3}, {s, 2.0 * s});
    for (const auto member :
         {&AxiStress::sigma_r, &AxiStress::sigma_z, &AxiStress::sigma_theta, &AxiStress::tau_rz}) {
      EXPECT_TRUE(Near(far.*member, near.*member, {.rel = 1e-14})) << s;
    }
  }
  // The issue's far points: finite, and as small as P / rho^2 says (0 once below 1e-308).
  const AxiStress far = boussinesq_stress({1.0, 0.25}, {1e200, 1e200});
  EXPECT_EQ(far.sigma_z, 0.0);
  const AxiStress edge = boussinesq_stress({1.0, 0.25}, {kMax, kMax});
  EXPECT_EQ(edge.sigma_r, 0.0);
  const AxiStress deep = boussinesq_stress({1.0, 0.25}, {0.0, 1e150});
  EXPECT_TRUE(Near(deep.sigma_z, -3.0 / (2.0 * pi) * 1e-300, {.rel = 1e-15}));
  // Next to the load point: P / (2 pi rho^2) overflows below rho ~ 1e-154.
  EXPECT_NO_THROW((void)boussinesq_stress({1.0, 0.25}, {0.0, 1e-150}));
  expect_refusal(
      [] {
        (void)boussinesq_stress({1.0, 0.25}, {0.0, 1e-160});
      },
      "overflows", "boussinesq next to the load");
}

TEST(ExtremeInputs, McEwenFarFieldIsFlamantsToSecondOrderAtEveryDistance) {
  // Far away the Hertzian pressure acts as its resultant P = 2ap, with a relative error
  // O((a/rho)^2) (its first moment vanishes). Taken as printed, m^2 - z^2 cancelled to O(a^2)
  // and lost (rho/a)^2 eps: 1e-4 at rho = 1e6 a. Bar: 2 (a/rho)^2 plus rounding.
  const McEwenLoad load{.a = 1.0, .p = 2.0};
  for (const double rho : {1e3, 1e6, 1e12, 1e100, 1e200}) {
    for (const double angle : {0.1, 0.7, 1.4, pi / 2}) {
      const PlanePoint at{rho * std::cos(angle), rho * std::sin(angle)};
      const PlaneStress m = mcewen_stress(load, at);
      const PlaneStress f = flamant_stress({.P = 2.0 * load.a * load.p}, at);
      const double scale = std::abs(f.sigma_z) + std::abs(f.sigma_x) + std::abs(f.tau_xz);
      const double bar = (2.0 / (rho * rho) + 1e-14) * scale;
      EXPECT_TRUE(Near(m.sigma_x, f.sigma_x, {.abs = bar})) << rho << ", " << angle;
      EXPECT_TRUE(Near(m.sigma_z, f.sigma_z, {.abs = bar})) << rho << ", " << angle;
      EXPECT_TRUE(Near(m.tau_xz, f.tau_xz, {.abs = bar})) << rho << ", " << angle;
    }
  }
  // The issue's far points: answered, down to the largest coordinates (the strip load and
  // Flamant too); the shear on the axis vanishes by symmetry to rounding.
  const PlaneStress far = mcewen_stress({1.0, 1.0}, {1e300, 1e300});
  // Flamant at 45 degrees: sigma_z = -(2P/pi) z^3 / r^4 = -(4/pi) / (4 1e300), P = 2.
  EXPECT_TRUE(Near(far.sigma_z, -1.0 / (pi * 1e300), {.rel = 1e-14}));
  EXPECT_LE(std::abs(mcewen_stress({1.0, 1.0}, {kMax, kMax}).sigma_x), 1e-307);
  // On the axis: sigma_z = -(2P/pi) / z, P = 2 a p = 2e10.
  const PlaneStress strip = strip_load_stress({1e10, 1.0}, {0.0, 1e300});
  EXPECT_TRUE(Near(strip.sigma_z, -4e-290 / pi, {.rel = 1e-14}));
  EXPECT_LE(std::abs(strip.tau_xz), 1e-15 * std::abs(strip.sigma_z));
  EXPECT_NO_THROW((void)strip_load_stress({1.0, 1.0}, {1e300, kMax}));
  EXPECT_NO_THROW((void)flamant_stress({1.0}, {-kMax, kMax}));
}

TEST(ExtremeInputs, McEwenAndStripAreScaleInvariant) {
  const PlanePoint points[] = {{0.0, 0.0}, {0.3, 0.2}, {-0.99, 0.01}, {2.0, 1.0}, {1.5, 0.0}};
  for (const double s : {1e-300, 1e300}) {
    for (const PlanePoint at : points) {
      const PlaneStress m1 = mcewen_stress({1.0, 2.0}, at);
      const PlaneStress ms = mcewen_stress({s, 2.0}, {at.x * s, at.z * s});
      const PlaneStress s1 = strip_load_stress({1.0, 2.0}, at.x == 1.5 ? PlanePoint{1.5, 0.1} : at);
      const PlaneStress ss = strip_load_stress(
          {s, 2.0}, at.x == 1.5 ? PlanePoint{1.5 * s, 0.1 * s} : PlanePoint{at.x * s, at.z * s});
      for (const auto member :
           {&PlaneStress::sigma_x, &PlaneStress::sigma_z, &PlaneStress::tau_xz}) {
        // Rounding of the scaled point (s is not a power of two): 1e-13 of p.
        EXPECT_TRUE(Near(ms.*member, m1.*member, {.rel = 1e-13, .abs = 1e-15})) << s;
        EXPECT_TRUE(Near(ss.*member, s1.*member, {.rel = 1e-13, .abs = 1e-15})) << s;
      }
    }
  }
  expect_refusal(
      [] {
        (void)mcewen_stress({1.0, kMax}, {0.0, 0.0});
      },
      "floating-point range", "mcewen p overflows");
}

}  // namespace
}  // namespace cs::oracles

// Frictional oracles: Cattaneo-Mindlin partial slip (plane strain, similar bodies), the
// tangential Flamant load and the semi-elliptic tangential traction's interior field, and the
// frictional patch tests. Checked independently: resultants by quadrature, |q| <= mu p, the
// stick condition (no relative tangential strain in |x| < c) by the principal-value integral of
// the traction, the limits Q -> 0 and Q -> mu P, superposition of tangential point loads,
// resultants across depth, the surface traction, the far field.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "oracles/cattaneo_mindlin.hpp"
#include "oracles/flamant_tangential.hpp"
#include "oracles/frictional_patch_test.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/hertz_tangential_traction.hpp"
#include "oracles/invalid_input.hpp"
#include "oracles/quadrature.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::oracles::test_friction {
namespace {

using cs::testing::Near;
using std::numbers::pi;

constexpr QuadratureTolerance kQuad{.abs = 0.0, .rel = 1e-12};

CattaneoMindlinPlane problem(double Q_over_mu_P, double mu = 0.3) {
  const double P = 2.5;
  return {.R = 40.0, .E = 1e3, .nu = 0.25, .P = P, .Q = Q_over_mu_P * mu * P, .mu = mu};
}

/// Integral of f over [-a, a] with breakpoints at +-c (the kinks of q).
template <typename F>
double over_contact(F f, double a, double c) {
  const std::array<double, 4> points{-a, -c, c, a};
  return integrate_with_breakpoints(f, points, kQuad).value;
}

// ---------------------------------------------------------------------------------------------
// Cattaneo-Mindlin

TEST(CattaneoMindlin, ContactIsHertzsWithTheContactModulusOfTwoSimilarBodies) {
  // Requirement: a and p0 are Hertz's with 1/E* = 2 (1 - nu^2)/E, i.e. the rigid-cylinder
  // oracle on a half-space of modulus E/2 (hertz_plane.hpp), and do not depend on Q.
  for (const double s : {0.0, 0.3, 0.99}) {
    const CattaneoMindlinPlane pr = problem(s);
    const CattaneoMindlinContact c = cattaneo_mindlin_contact(pr);
    const HertzPlaneContact h = hertz_plane_contact({pr.R, 0.5 * pr.E, pr.nu, pr.P});
    EXPECT_TRUE(Near(c.contact_half_width_a, h.contact_half_width_a, {.rel = 1e-15}));
    EXPECT_TRUE(Near(c.p0, h.p_max, {.rel = 1e-15}));
    EXPECT_TRUE(Near(c.p_mean, h.p_mean, {.rel = 1e-15}));
    // Q = s mu P rounds: Q/(mu P) carries 1e-16, c/a that over 2 (1 - s): 1e-14.
    EXPECT_TRUE(Near(c.c_over_a, std::sqrt(1.0 - s), {.rel = 1e-14}));
  }
}

TEST(CattaneoMindlin, TractionsIntegrateToTheLoadsAndStayInsideTheFrictionCone) {
  double worst_resultant = 0.0;
  for (const double s : {1e-6, 0.1, 0.5, 0.9, 1.0 - 1e-9}) {
    const CattaneoMindlinPlane pr = problem(s);
    const CattaneoMindlinContact c = cattaneo_mindlin_contact(pr);
    const double a = c.contact_half_width_a;
    const double cs = c.stick_half_width_c;
    auto q = [&](double x) { return cattaneo_mindlin_shear(c, x); };
    auto p = [&](double x) { return cattaneo_mindlin_pressure(c, x); };
    // Quadrature to 1e-12 around the square-root ends and kinks: 1e-10.
    const double Q = over_contact(q, a, cs);
    EXPECT_TRUE(Near(Q, pr.Q, {.rel = 1e-10})) << "Q/(mu P) = " << s;
    EXPECT_TRUE(Near(over_contact(p, a, cs), pr.P, {.rel = 1e-10})) << s;
    worst_resultant = std::max(worst_resultant, std::abs(Q - pr.Q) / pr.Q);
    // |q| <= mu p everywhere, = mu p in the slip zones (rounding: 1e-15), and the peak is q(c).
    double scan_max = 0.0;
    for (int i = -4000; i <= 4000; ++i) {
      const double x = a * i / 4000.0;
      const double mu_p = pr.mu * p(x);
      ASSERT_LE(q(x), mu_p * (1.0 + 1e-15)) << s << ", x = " << x;
      ASSERT_GE(q(x), 0.0) << s << ", x = " << x;
      if (std::abs(x) > cs)
        ASSERT_TRUE(Near(q(x), mu_p, {.rel = 1e-15})) << s << ", x = " << x;
      else
        ASSERT_LT(q(x), mu_p) << "stick zone strictly inside the cone: " << s << ", x = " << x;
      scan_max = std::max(scan_max, q(x));
    }
    EXPECT_LE(scan_max, c.q_peak * (1.0 + 1e-14)) << s;
    // q(c) = mu p0 (1 - c^2/a^2)^(1/2) from the rounded c: its relative error is
    // eps / (2 (1 - c/a)) (3e-10 at Q/(mu P) = 1e-6), q_peak has none.
    EXPECT_TRUE(Near(q(cs), c.q_peak, {.rel = 1e-15 / (1.0 - c.c_over_a)})) << s;
    EXPECT_TRUE(Near(c.q_peak_over_p_mean, c.q_peak / c.p_mean, {.rel = 1e-15})) << s;
  }
  std::printf("[   info   ] Cattaneo-Mindlin: worst |int q dx - Q| / Q = %.2e\n", worst_resultant);
}

TEST(CattaneoMindlin, StickZoneHasNoRelativeTangentialStrain) {
  // For similar bodies the relative tangential surface strain is proportional to
  // PV int q(s) / (x - s) ds (Johnson Eq. 2.25b, the pressure terms cancel between the
  // bodies): zero in the stick zone |x| < c, so c is the right stick half-width; non-zero in
  // the slip zones. QAWC to 1e-11 next to square-root ends and kinks: 1e-8 of mu p0.
  for (const double s : {0.3, 0.8}) {
    const CattaneoMindlinContact c = cattaneo_mindlin_contact(problem(s));
    const double a = c.contact_half_width_a;
    const double cs = c.stick_half_width_c;
    const double scale = c.mu * c.p0;
    for (const double t : {0.0, 0.3, 0.7, 0.95, 1.1, 1.3}) {
      const double x = t * cs;
      if (x >= a)
        continue;
      auto q = [&](double xs) { return cattaneo_mindlin_shear(c, xs); };
      const double pv = x == 0.0 ? 0.0
                                 : integrate_cauchy_principal_value(
                                       q, -a, a, x, {.abs = 1e-13 * scale, .rel = 1e-11})
                                       .value;
      if (t < 1.0)
        EXPECT_TRUE(Near(pv, 0.0, {.abs = 1e-8 * scale})) << s << ", x/c = " << t;
      else
        EXPECT_GT(std::abs(pv), 1e-3 * scale) << s << ", x/c = " << t;
    }
  }
}

TEST(CattaneoMindlin, LimitsNoTangentialLoadAndFullSliding) {
  // Q -> 0: c -> a and q -> 0 as Q/(mu P) (the peak as its square root).
  const CattaneoMindlinContact light = cattaneo_mindlin_contact(problem(1e-12));
  EXPECT_TRUE(Near(light.c_over_a, 1.0, {.rel = 1e-12}));
  EXPECT_LT(light.q_peak_over_p0, 1e-6 * light.mu * 1.0000001);
  // At x = 0: mu p0 (1 - c/a) = mu p0 s / (1 + c/a) -> mu p0 s / 2, to full precision.
  EXPECT_TRUE(
      Near(cattaneo_mindlin_shear(light, 0.0), 0.5e-12 * light.mu * light.p0, {.rel = 1e-11}));
  // Q -> mu P: c -> 0 and q -> mu p everywhere (within mu p0 c/a at the centre).
  const CattaneoMindlinContact sliding = cattaneo_mindlin_contact(problem(1.0 - 1e-12));
  EXPECT_LT(sliding.c_over_a, 1.1e-6);
  for (const double x : {0.0, 0.3, 0.9}) {
    const double xa = x * sliding.contact_half_width_a;
    const double mu_p = sliding.mu * cattaneo_mindlin_pressure(sliding, xa);
    EXPECT_TRUE(Near(cattaneo_mindlin_shear(sliding, xa), mu_p, {.abs = 1.1e-6 * mu_p})) << x;
  }
  EXPECT_TRUE(Near(sliding.q_peak_over_p0, sliding.mu, {.rel = 1e-12}));
}

TEST(CattaneoMindlin, BadInputIsRefusedWithItsCause) {
  struct Case {
    std::string label;
    CattaneoMindlinPlane problem;
    std::string mention;
  };
  const CattaneoMindlinPlane ok = problem(0.5);
  auto with = [&](auto edit) {
    CattaneoMindlinPlane p = ok;
    edit(p);
    return p;
  };
  const std::vector<Case> cases{
      {"mu < 0", with([](auto& p) { p.mu = -0.1; }), "friction coefficient mu"},
      {"mu nan", with([](auto& p) { p.mu = std::nan(""); }), "friction coefficient mu"},
      {"mu inf", with([](auto& p) { p.mu = INFINITY; }), "[0, 10]"},
      {"mu > 10", with([](auto& p) { p.mu = 10.5; }), "(got 10.5)"},
      {"Q = mu P", with([](auto& p) { p.Q = p.mu * p.P; }),
       "Q >= mu P: the stick oracle needs Q < mu P"},
      {"Q > mu P", with([](auto& p) { p.Q = 2.0 * p.mu * p.P; }),
       "the stick oracle needs Q < mu P"},
      {"mu = 0 (no stick possible)", with([](auto& p) { p.mu = 0.0, p.Q = 0.0; }), "Q >= mu P"},
      {"Q < 0", with([](auto& p) { p.Q = -1.0; }), "tangential load"},
      {"R = 0", with([](auto& p) { p.R = 0.0; }), "radius R"},
      {"nu = 0.5", with([](auto& p) { p.nu = 0.5; }), "nu"},
      {"P overflow", with([](auto& p) { p.P = 1e300, p.R = 1e300, p.E = 1e-300; }), "range"},
  };
  for (const Case& c : cases) {
    try {
      (void)cattaneo_mindlin_contact(c.problem);
      ADD_FAILURE() << c.label << ": no exception";
    } catch (const InvalidInput& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.mention), std::string::npos) << c.label << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << c.label;
    }
  }
  // mu = 10 is the largest accepted.
  EXPECT_NO_THROW((void)cattaneo_mindlin_contact(with([](auto& p) { p.mu = 10.0; })));
}

// ---------------------------------------------------------------------------------------------
// Tangential fields

/// The stress at `at` of tangential Flamant loads traction(s) ds over |s| < half_width.
template <typename Traction>
PlaneStress tangential_superposition(Traction traction, double half_width, double q,
                                     PlanePoint at) {
  std::vector<double> points{-half_width, half_width};
  for (const double s : {at.x - at.z, at.x, at.x + at.z}) {
    if (s > -half_width && s < half_width)
      points.push_back(s);
  }
  std::sort(points.begin(), points.end());
  const QuadratureTolerance tol{.abs = 1e-13 * q, .rel = 1e-12};
  auto component = [&](auto member) {
    return integrate_with_breakpoints(
               [&](double s) {
                 if (at.x == s && at.z == 0.0)
                   return 0.0;
                 return traction(s) *
                        flamant_tangential_stress({.Q = 1.0}, {at.x - s, at.z}).*member;
               },
               points, tol)
        .value;
  };
  return {component(&PlaneStress::sigma_x), component(&PlaneStress::sigma_z),
          component(&PlaneStress::tau_xz)};
}

TEST(TangentialTraction, FieldIsTheSuperpositionOfTangentialFlamantLoads) {
  // The same 29 points as the McEwen check (test_superposition.cpp), and the same bar: 1e-8
  // relative, 1e-11 q0 absolute for components that vanish by symmetry.
  const HertzTangentialTraction load{.a = 1.0, .q0 = 2.5};
  std::vector<PlanePoint> points;
  for (const double x : {0.0, 0.45, -0.8, 1.6, -3.0}) {
    for (const double z : {0.2, 1.0, 3.5})
      points.push_back({x, z});
  }
  for (const PlanePoint p : {PlanePoint{0.3, 1e-3},
                             {-0.5, 1e-4},
                             {2.0, 1e-3},
                             {-1.5, 1e-4},
                             {0.999, 1e-3},
                             {1.001, 1e-3},
                             {1.0, 2e-3},
                             {-1.0, 1e-4},
                             {0.99, 0.01},
                             {1.01, 0.01},
                             {-0.98, 0.05},
                             {1.05, 0.05},
                             {0.0, 1e-5},
                             {7.0, 0.5}})
    points.push_back(p);
  double worst = 0.0;
  for (const PlanePoint at : points) {
    const PlaneStress closed = hertz_tangential_traction_stress(load, at);
    const PlaneStress sum = tangential_superposition(
        [&](double s) { return load.q0 * std::sqrt(std::max(0.0, (1.0 - s) * (1.0 + s))); }, load.a,
        load.q0, at);
    const cs::testing::Tolerance tol{.rel = 1e-8, .abs = 1e-11 * load.q0};
    EXPECT_TRUE(Near(closed.sigma_x, sum.sigma_x, tol)) << at.x << ", " << at.z;
    EXPECT_TRUE(Near(closed.sigma_z, sum.sigma_z, tol)) << at.x << ", " << at.z;
    EXPECT_TRUE(Near(closed.tau_xz, sum.tau_xz, tol)) << at.x << ", " << at.z;
    for (const auto m : {&PlaneStress::sigma_x, &PlaneStress::sigma_z, &PlaneStress::tau_xz}) {
      const double scale = std::max(std::abs(sum.*m), 1e-3 * load.q0);
      worst = std::max(worst, std::abs(closed.*m - sum.*m) / scale);
    }
  }
  std::printf("[   info   ] tangential traction vs tangential Flamant superposition: worst %.2e\n",
              worst);
}

TEST(TangentialTraction, SurfaceCarriesTheTractionAndNothingElse) {
  // On z = 0 (sign convention of docs/conventions.md, z into the body): tau_xz = -q(x), so the
  // traction on the body is t_x = -tau_xz = +q; sigma_z = 0; sigma_x = -2 q0 x / a under the
  // load (compression ahead, tension behind), -2 (q0/a)(x - sign(x)(x^2 - a^2)^(1/2)) outside.
  const HertzTangentialTraction load{.a = 2.0, .q0 = 3.0};
  for (const double x : {-5.0, -2.0, -1.999, -1.2, 0.0, 0.4, 1.9, 2.0, 2.5, 40.0}) {
    const PlaneStress s = hertz_tangential_traction_stress(load, {x, 0.0});
    const double xi = x / load.a;
    const double q = std::abs(xi) < 1.0 ? load.q0 * std::sqrt(1.0 - xi * xi) : 0.0;
    const double sigma_x =
        std::abs(xi) <= 1.0 ? -2.0 * load.q0 * xi
                            : -2.0 * load.q0 * (xi - std::copysign(std::sqrt(xi * xi - 1.0), xi));
    EXPECT_TRUE(Near(s.tau_xz, -q, {.rel = 1e-14, .abs = 1e-15})) << x;
    EXPECT_EQ(s.sigma_z, 0.0) << x;
    EXPECT_TRUE(Near(s.sigma_x, sigma_x, {.rel = 1e-12, .abs = 1e-15})) << x;
    if (std::abs(x) == load.a)
      continue;  // at an edge the field approaches its value as (z/a)^(1/2)
    // Continuous onto the surface from z = 1e-9 a: within O(q0 z / d), d = distance to an edge.
    const PlaneStress below = hertz_tangential_traction_stress(load, {x, 2e-9});
    const double d = std::max(std::abs(std::abs(x) - load.a), 1e-3);
    const double bar = 1e-8 * load.q0 / std::sqrt(d) + 1e-14;
    EXPECT_TRUE(Near(below.tau_xz, s.tau_xz, {.abs = 10 * bar})) << x;
    EXPECT_TRUE(Near(below.sigma_x, s.sigma_x, {.abs = 10 * bar})) << x;
  }
}

TEST(TangentialTraction, FieldsCarryTheTangentialLoadAcrossEveryDepth) {
  // Equilibrium of the layer above z = h: int tau_xz(x, h) dx = -Q, int sigma_z dx = 0.
  const FlamantTangentialLoad point{.Q = 1.5};
  const HertzTangentialTraction spread{.a = 0.5, .q0 = 3.0};
  const double Q_spread = 0.5 * pi * spread.a * spread.q0;
  for (const double h : {0.05, 0.5, 4.0}) {
    // An absolute floor of 1e-13 of the load: the sigma_z resultant is exactly 0.
    const QuadratureTolerance tol{.abs = 1e-13, .rel = 1e-12};
    auto over_line = [&](auto field, auto member) {
      const auto near = integrate([&](double x) { return field({x, h}).*member; }, -2.0, 2.0, tol);
      const auto right = integrate_to_infinity(
          [&](double x) {
            return field({x, h}).*member;
          },
          2.0, tol);
      const auto left = integrate_to_infinity(
          [&](double x) {
            return field({-x, h}).*member;
          },
          2.0, tol);
      return near.value + right.value + left.value;
    };
    auto flamant = [&](PlanePoint p) { return flamant_tangential_stress(point, p); };
    auto hertz = [&](PlanePoint p) { return hertz_tangential_traction_stress(spread, p); };
    EXPECT_TRUE(Near(over_line(flamant, &PlaneStress::tau_xz), -point.Q, {.rel = 1e-10})) << h;
    EXPECT_TRUE(Near(over_line(flamant, &PlaneStress::sigma_z), 0.0, {.abs = 1e-10})) << h;
    EXPECT_TRUE(Near(over_line(hertz, &PlaneStress::tau_xz), -Q_spread, {.rel = 1e-10})) << h;
    EXPECT_TRUE(Near(over_line(hertz, &PlaneStress::sigma_z), 0.0, {.abs = 1e-10})) << h;
  }
}

TEST(TangentialTraction, FarFieldIsTheTangentialFlamantFieldOfTheResultant) {
  // Q = pi a q0 / 2; the traction's first moment vanishes: O((a/r)^2) of the field's scale
  // (2Q/pi)/r at every distance (scale-free evaluation). Bar: 2 (a/r)^2 plus rounding.
  const HertzTangentialTraction load{.a = 1.0, .q0 = 2.0};
  const FlamantTangentialLoad point{.Q = 0.5 * pi * load.a * load.q0};
  for (const double rho : {1e2, 1e4, 1e8, 1e100, 1e250}) {
    for (const double angle : {0.1, 0.8, 1.5}) {
      const PlanePoint at{rho * std::cos(angle), rho * std::sin(angle)};
      const PlaneStress t = hertz_tangential_traction_stress(load, at);
      const PlaneStress f = flamant_tangential_stress(point, at);
      const double scale = 2.0 * point.Q / (pi * rho);
      const double bar = (2.0 / (rho * rho) + 1e-14) * scale;
      EXPECT_TRUE(Near(t.sigma_x, f.sigma_x, {.abs = bar})) << rho << ", " << angle;
      EXPECT_TRUE(Near(t.sigma_z, f.sigma_z, {.abs = bar})) << rho << ", " << angle;
      EXPECT_TRUE(Near(t.tau_xz, f.tau_xz, {.abs = bar})) << rho << ", " << angle;
    }
  }
}

TEST(TangentialTraction, FullSlidingHertzFieldIsMuTimesTheCattaneoMindlinLimit) {
  // The sliding traction mu p(x) is the field with q0 = mu p0; the bad inputs are refused.
  EXPECT_THROW((void)hertz_tangential_traction_stress({1.0, 0.0}, {0.0, 1.0}), InvalidInput);
  EXPECT_THROW((void)hertz_tangential_traction_stress({0.0, 1.0}, {0.0, 1.0}), InvalidInput);
  EXPECT_THROW((void)hertz_tangential_traction_stress({1.0, 1.0}, {0.0, -1.0}), InvalidInput);
  EXPECT_THROW((void)flamant_tangential_stress({1.0}, {0.0, 0.0}), InvalidInput);
  EXPECT_THROW((void)flamant_tangential_stress({std::nan("")}, {1.0, 1.0}), InvalidInput);
  // Linear in q0, odd in x (for sigma_x, sigma_z), even in x (for tau_xz).
  const PlaneStress s1 = hertz_tangential_traction_stress({1.0, 1.0}, {0.3, 0.4});
  const PlaneStress s2 = hertz_tangential_traction_stress({1.0, -2.0}, {-0.3, 0.4});
  EXPECT_TRUE(Near(s2.sigma_x, 2.0 * s1.sigma_x, {.rel = 1e-14}));
  EXPECT_TRUE(Near(s2.sigma_z, 2.0 * s1.sigma_z, {.rel = 1e-14}));
  EXPECT_TRUE(Near(s2.tau_xz, -2.0 * s1.tau_xz, {.rel = 1e-14}));
}

// ---------------------------------------------------------------------------------------------
// Frictional patch tests

TEST(FrictionalPatch, StickTransmitsTheShearExactlyAndSlipTransmitsMuP) {
  const PlaneStress stick =
      frictional_patch_stick_stress({.p = 2.0, .tau = 0.59, .mu = 0.3}, {0.4, 0.7});
  EXPECT_EQ(stick.sigma_z, -2.0);
  EXPECT_EQ(stick.sigma_x, 0.0);
  EXPECT_EQ(stick.tau_xz, -0.59);
  const PlaneStress slip = frictional_patch_slip_stress({.p = 2.0, .mu = 0.3}, {0.4, 0.7});
  EXPECT_EQ(slip.sigma_z, -2.0);
  EXPECT_EQ(slip.tau_xz, -0.3 * 2.0);
  try {
    (void)frictional_patch_stick_stress({.p = 2.0, .tau = 0.6, .mu = 0.3}, {0.0, 0.0});
    ADD_FAILURE() << "tau = mu p must be refused by the stick oracle";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("Q >= mu P: the stick oracle needs Q < mu P"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW((void)frictional_patch_stick_stress({2.0, -0.1, 0.3}, {0.0, 0.0}), InvalidInput);
  EXPECT_THROW((void)frictional_patch_slip_stress({2.0, 11.0}, {0.0, 0.0}), InvalidInput);
  EXPECT_THROW((void)frictional_patch_slip_stress({2.0, -1.0}, {0.0, 0.0}), InvalidInput);
  EXPECT_THROW((void)frictional_patch_slip_stress({0.0, 0.3}, {0.0, 0.0}), InvalidInput);
}

}  // namespace
}  // namespace cs::oracles::test_friction

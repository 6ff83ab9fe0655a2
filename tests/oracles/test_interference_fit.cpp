// Lame interference fits (shaft in a ring, plane strain; sphere in a shell), checked
// independently of the formulas they use: compatibility u_outer(b) - u_inner(b) = delta from the
// displacement fields, continuity of sigma_r across the interface, a traction-free outer
// surface, equilibrium and Hooke's law with the strains of the displacement field by finite
// differences, the one-material textbook formulas, the limit c -> infinity, the Cartesian
// helpers, scale invariance, and the refusals at the edges of the domain.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "oracles/interference_fit.hpp"
#include "oracles/invalid_input.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::oracles::test_interference_fit {
namespace {

using cs::testing::Near;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Fits with thick and thin rings, unequal and equal materials, an infinite outer body.
std::vector<InterferenceFit> fits() {
  const LameMaterial steel{2.1e5, 0.3};
  const LameMaterial bronze{1.1e5, 0.34};
  const LameMaterial rubbery{50.0, 0.49};
  return {
      {1.0, 2.0, 1e-3, steel, steel},      {1.0, 1.05, 1e-3, steel, bronze},
      {1.0, 8.0, 5e-3, bronze, steel},     {3.0, 3.3, 1e-4, rubbery, steel},
      {0.2, 1.0, 2e-3, steel, rubbery},    {1.0, kInf, 1e-3, bronze, steel},
      {2.0, 1e6, 1e-2, steel, {3e3, 0.0}},
  };
}

/// Fourth-order central first derivative.
template <typename F>
double d1(F f, double t, double h) {
  return (f(t - 2 * h) - 8 * f(t - h) + 8 * f(t + h) - f(t + 2 * h)) / (12 * h);
}

/// Radii of a body, away from its ends by two finite-difference steps.
std::vector<double> radii(const InterferenceFit& fit, FitBody body) {
  if (body == FitBody::kInner)
    return {0.1 * fit.b, 0.5 * fit.b, 0.97 * fit.b};
  const double c = std::isinf(fit.c) ? 100.0 * fit.b : fit.c;
  return {fit.b + 0.03 * (c - fit.b), 0.5 * (fit.b + c), c - 0.03 * (c - fit.b)};
}

TEST(InterferenceFit, CompatibilityContinuityAndFreeOuterSurface) {
  // Requirement: the displacement fields close the interference exactly, sigma_r is continuous
  // at r = b (= -p), and the outer surface is free. Rounding: 1e-14.
  for (const InterferenceFit& fit : fits()) {
    const double p_cyl = interference_fit_cylinder_pressure(fit);
    const double p_sph = interference_fit_sphere_pressure(fit);
    const auto ci = interference_fit_cylinder_state(fit, FitBody::kInner, fit.b);
    const auto co = interference_fit_cylinder_state(fit, FitBody::kOuter, fit.b);
    const auto si = interference_fit_sphere_state(fit, FitBody::kInner, fit.b);
    const auto so = interference_fit_sphere_state(fit, FitBody::kOuter, fit.b);
    const std::string label = "b = " + format_value(fit.b) + ", c = " + format_value(fit.c);
    EXPECT_TRUE(Near(co.u_r - ci.u_r, fit.delta, {.rel = 1e-14})) << label;
    EXPECT_TRUE(Near(so.u_r - si.u_r, fit.delta, {.rel = 1e-14})) << label;
    EXPECT_TRUE(Near(ci.sigma_r, -p_cyl, {.rel = 1e-15})) << label;
    EXPECT_TRUE(Near(co.sigma_r, -p_cyl, {.rel = 1e-14})) << label;
    EXPECT_TRUE(Near(si.sigma_r, -p_sph, {.rel = 1e-15})) << label;
    EXPECT_TRUE(Near(so.sigma_r, -p_sph, {.rel = 1e-14})) << label;
    EXPECT_GT(p_cyl, 0.0);
    EXPECT_GT(p_sph, 0.0);
    if (!std::isinf(fit.c)) {
      EXPECT_EQ(interference_fit_cylinder_state(fit, FitBody::kOuter, fit.c).sigma_r, 0.0);
      EXPECT_EQ(interference_fit_sphere_state(fit, FitBody::kOuter, fit.c).sigma_r, 0.0);
    }
  }
}

TEST(InterferenceFit, EquilibriumAndHookesLawWithTheDisplacementsStrains) {
  // d sigma_r/dr + (sigma_r - sigma_theta)/r = 0 (cylinder), + 2 (sigma_r - sigma_theta)/r
  // (sphere); and the stresses are Hooke's law of eps_r = du/dr, eps_theta = u/r (plane strain:
  // eps_z = 0). Fourth-order differences with h = 1e-3 r: truncation ~1e-12, rounding ~1e-13;
  // bars 1e-9 of p/r and 1e-9 of p.
  double worst_equilibrium = 0.0;
  double worst_hooke = 0.0;
  for (const InterferenceFit& fit : fits()) {
    for (const FitBody body : {FitBody::kInner, FitBody::kOuter}) {
      const LameMaterial m = body == FitBody::kInner ? fit.inner : fit.outer;
      const double lambda = m.E * m.nu / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu));
      const double two_G = m.E / (1.0 + m.nu);
      for (const double r : radii(fit, body)) {
        const double h = 1e-3 * std::min(r, std::isinf(fit.c) ? r : fit.c - fit.b);
        // Cylinder.
        auto cyl = [&](double s) { return interference_fit_cylinder_state(fit, body, s); };
        const auto c = cyl(r);
        const double p = interference_fit_cylinder_pressure(fit);
        const double eq_c =
            d1([&](double s) { return cyl(s).sigma_r; }, r, h) + (c.sigma_r - c.sigma_theta) / r;
        const double er = d1([&](double s) { return cyl(s).u_r; }, r, h);
        const double et = c.u_r / r;
        const double hooke_c = std::max({std::abs(lambda * (er + et) + two_G * er - c.sigma_r),
                                         std::abs(lambda * (er + et) + two_G * et - c.sigma_theta),
                                         std::abs(lambda * (er + et) - c.sigma_z)});
        // Sphere.
        auto sph = [&](double s) { return interference_fit_sphere_state(fit, body, s); };
        const auto s = sph(r);
        const double ps = interference_fit_sphere_pressure(fit);
        const double eq_s = d1([&](double t) { return sph(t).sigma_r; }, r, h) +
                            2.0 * (s.sigma_r - s.sigma_theta) / r;
        const double sr = d1([&](double t) { return sph(t).u_r; }, r, h);
        const double st = s.u_r / r;
        const double hooke_s =
            std::max(std::abs(lambda * (sr + 2 * st) + two_G * sr - s.sigma_r),
                     std::abs(lambda * (sr + 2 * st) + two_G * st - s.sigma_theta));
        const std::string label = "b = " + format_value(fit.b) + ", c = " + format_value(fit.c) +
                                  ", r = " + format_value(r);
        EXPECT_LT(std::abs(eq_c) * r / p, 1e-9) << label;
        EXPECT_LT(std::abs(eq_s) * r / ps, 1e-9) << label;
        EXPECT_LT(hooke_c / p, 1e-9) << label;
        EXPECT_LT(hooke_s / ps, 1e-9) << label;
        worst_equilibrium =
            std::max({worst_equilibrium, std::abs(eq_c) * r / p, std::abs(eq_s) * r / ps});
        worst_hooke = std::max({worst_hooke, hooke_c / p, hooke_s / ps});
      }
    }
  }
  std::printf("[   info   ] interference fits: worst equilibrium residual %.2e p/r, Hooke %.2e p\n",
              worst_equilibrium, worst_hooke);
}

TEST(InterferenceFit, OneMaterialGivesTheTextbookShrinkFits) {
  // Timoshenko and Goodier: p = (delta/b) E (1 - b^2/c^2) / (2 (1 - nu^2)) (plane strain) and
  // p = (2/3)(delta/b) E (1 - b^3/c^3) / (1 - nu) (sphere in a shell).
  for (const double c : {1.1, 2.0, 10.0}) {
    const InterferenceFit fit{1.0, c, 2e-3, {7e4, 0.33}, {7e4, 0.33}};
    const double beta = 1.0 / c;
    EXPECT_TRUE(Near(interference_fit_cylinder_pressure(fit),
                     2e-3 * 7e4 * (1.0 - beta * beta) / (2.0 * (1.0 - 0.33 * 0.33)),
                     {.rel = 1e-14}))
        << c;
    EXPECT_TRUE(Near(interference_fit_sphere_pressure(fit),
                     2.0 / 3.0 * 2e-3 * 7e4 * (1.0 - beta * beta * beta) / (1.0 - 0.33),
                     {.rel = 1e-14}))
        << c;
  }
}

TEST(InterferenceFit, LargeOuterBodiesTendToTheHoleInAnInfinitePlateAndBody) {
  // c -> inf: the pressure converges to the c = inf value as (b/c)^2 (cylinder) and (b/c)^3
  // (sphere); at c = inf the plate is Lame's hole: sigma_theta = -sigma_r = p b^2 / r^2,
  // u = (1 + nu) p b^2 / (E r); the body: sigma_theta = -sigma_r / 2 = p b^3 / (2 R^3).
  const LameMaterial shaft{2e5, 0.3};
  const LameMaterial plate{7e4, 0.25};
  const InterferenceFit infinite{1.0, kInf, 1e-3, shaft, plate};
  const double p_cyl = interference_fit_cylinder_pressure(infinite);
  const double p_sph = interference_fit_sphere_pressure(infinite);
  EXPECT_TRUE(Near(p_cyl, 1e-3 / ((1.25) / 7e4 + 1.3 * 0.4 / 2e5), {.rel = 1e-15}));
  EXPECT_TRUE(Near(p_sph, 1e-3 / ((0.625) / 7e4 + 0.4 / 2e5), {.rel = 1e-15}));
  for (const double c : {1e2, 1e3, 1e4}) {
    const InterferenceFit finite{1.0, c, 1e-3, shaft, plate};
    const double e_cyl = std::abs(interference_fit_cylinder_pressure(finite) / p_cyl - 1.0);
    const double e_sph = std::abs(interference_fit_sphere_pressure(finite) / p_sph - 1.0);
    EXPECT_LT(e_cyl, 2.0 / (c * c)) << c;
    EXPECT_GT(e_cyl, 0.1 / (c * c)) << c;
    EXPECT_LT(e_sph, 2.0 / (c * c * c) + 1e-15) << c;
  }
  for (const double r : {1.0, 2.0, 50.0}) {
    const auto s = interference_fit_cylinder_state(infinite, FitBody::kOuter, r);
    EXPECT_TRUE(Near(s.sigma_theta, p_cyl / (r * r), {.rel = 1e-15})) << r;
    EXPECT_TRUE(Near(s.sigma_r, -p_cyl / (r * r), {.rel = 1e-15})) << r;
    EXPECT_TRUE(Near(s.u_r, 1.25 * p_cyl / (7e4 * r), {.rel = 1e-15})) << r;
    const auto t = interference_fit_sphere_state(infinite, FitBody::kOuter, r);
    EXPECT_TRUE(Near(t.sigma_theta, p_sph / (2.0 * r * r * r), {.rel = 1e-15})) << r;
    EXPECT_TRUE(Near(t.sigma_r, -p_sph / (r * r * r), {.rel = 1e-15})) << r;
  }
}

TEST(InterferenceFit, CartesianComponentsRotateThePolarState) {
  // On the interface every point carries the normal traction -p whatever its angle, and the
  // invariants (trace, largest shear) are those of the polar state.
  const InterferenceFit fit{1.0, 1.6, 1e-3, {2e5, 0.3}, {1e5, 0.3}};
  const double p = interference_fit_cylinder_pressure(fit);
  const double ps = interference_fit_sphere_pressure(fit);
  for (const double angle : {0.0, 0.3, 0.785, 1.2, 1.5707963267948966}) {
    const double cs = std::cos(angle);
    const double sn = std::sin(angle);
    const PlaneStress s = interference_fit_cylinder_stress(fit, FitBody::kOuter, {cs, sn});
    // Normal traction on the circle r = 1: n = (cos, sin).
    const double t_n = s.sigma_x * cs * cs + 2.0 * s.tau_xz * cs * sn + s.sigma_z * sn * sn;
    EXPECT_TRUE(Near(t_n, -p, {.rel = 1e-14})) << angle;
    const auto polar = interference_fit_cylinder_state(fit, FitBody::kOuter, 1.0);
    EXPECT_TRUE(Near(s.sigma_x + s.sigma_z, polar.sigma_r + polar.sigma_theta, {.rel = 1e-14}));
    const AxiStress a = interference_fit_sphere_stress(fit, FitBody::kOuter, {sn, cs});
    const double a_n = a.sigma_r * sn * sn + 2.0 * a.tau_rz * sn * cs + a.sigma_z * cs * cs;
    EXPECT_TRUE(Near(a_n, -ps, {.rel = 1e-14})) << angle;
  }
  // The shaft is in uniform hydrostatic plane compression, the sphere in uniform compression.
  const PlaneStress centre = interference_fit_cylinder_stress(fit, FitBody::kInner, {0.0, 0.0});
  EXPECT_EQ(centre.sigma_x, -p);
  EXPECT_EQ(centre.tau_xz, 0.0);
}

TEST(InterferenceFit, ScaleInvariance) {
  // b, c, delta scaled by s: the same pressure and stresses, displacements scaled by s.
  const InterferenceFit unit{1.0, 2.5, 1e-3, {2e5, 0.3}, {1e5, 0.35}};
  for (const double s : {1e-200, 1e200}) {
    const InterferenceFit scaled{s, 2.5 * s, 1e-3 * s, unit.inner, unit.outer};
    EXPECT_TRUE(Near(interference_fit_cylinder_pressure(scaled),
                     interference_fit_cylinder_pressure(unit), {.rel = 1e-14}));
    EXPECT_TRUE(Near(interference_fit_sphere_pressure(scaled),
                     interference_fit_sphere_pressure(unit), {.rel = 1e-14}));
    const auto a = interference_fit_sphere_state(scaled, FitBody::kOuter, 1.7 * s);
    const auto b = interference_fit_sphere_state(unit, FitBody::kOuter, 1.7);
    EXPECT_TRUE(Near(a.sigma_theta, b.sigma_theta, {.rel = 1e-14}));
    EXPECT_TRUE(Near(a.u_r / s, b.u_r, {.rel = 1e-14}));
  }
}

TEST(InterferenceFit, RefusalsAtTheEdgesOfTheDomain) {
  const InterferenceFit ok{1.0, 2.0, 1e-3, {2e5, 0.3}, {2e5, 0.3}};
  struct Case {
    std::string label;
    InterferenceFit fit;
    std::string mention;
  };
  auto with = [&](auto edit) {
    InterferenceFit f = ok;
    edit(f);
    return f;
  };
  const std::vector<Case> cases{
      {"delta = 0", with([](auto& f) { f.delta = 0.0; }), "interference delta"},
      {"delta < 0", with([](auto& f) { f.delta = -1e-3; }), "interference delta"},
      {"delta/b just above 1e-2", with([](auto& f) { f.delta = 1.0000001e-2; }),
       "small-strain limit"},
      {"c = b", with([](auto& f) { f.c = 1.0; }), "must exceed"},
      {"c < b", with([](auto& f) { f.c = 0.5; }), "must exceed"},
      {"c nan", with([](auto& f) { f.c = std::nan(""); }), "must exceed"},
      {"b = 0", with([](auto& f) { f.b = 0.0; }), "interface radius b"},
      {"E inner = 0", with([](auto& f) { f.inner.E = 0.0; }), "inner body"},
      {"nu outer = 0.5", with([](auto& f) { f.outer.nu = 0.5; }), "nu"},
  };
  for (const Case& c : cases) {
    for (const bool sphere : {false, true}) {
      try {
        (void)(sphere ? interference_fit_sphere_pressure(c.fit)
                      : interference_fit_cylinder_pressure(c.fit));
        ADD_FAILURE() << c.label << ": no exception";
      } catch (const InvalidInput& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(c.mention), std::string::npos) << c.label << ": " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << c.label;
      }
    }
  }
  // The edges themselves are accepted: delta/b = 1e-2, c just above b.
  EXPECT_NO_THROW((void)interference_fit_cylinder_pressure(with([](auto& f) { f.delta = 1e-2; })));
  EXPECT_NO_THROW((void)interference_fit_sphere_pressure(with([](auto& f) { f.c = 1.0 + 1e-12; })));
  // Radii outside the body asked for.
  EXPECT_THROW((void)interference_fit_cylinder_state(ok, FitBody::kInner, 1.01), InvalidInput);
  EXPECT_THROW((void)interference_fit_cylinder_state(ok, FitBody::kOuter, 0.99), InvalidInput);
  EXPECT_THROW((void)interference_fit_sphere_state(ok, FitBody::kOuter, 2.01), InvalidInput);
  EXPECT_THROW((void)interference_fit_sphere_state(ok, FitBody::kInner, -0.1), InvalidInput);
  EXPECT_THROW((void)interference_fit_sphere_stress(ok, FitBody::kInner, {0.9, 0.9}), InvalidInput);
}

}  // namespace
}  // namespace cs::oracles::test_interference_fit

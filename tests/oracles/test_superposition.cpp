// Every closed-form interior field equals the numerical superposition of point-load solutions
// over its surface pressure: McEwen (Eqs. 11-12) and the strip load (Eqs. 35-36) against
// Flamant line loads over the pressure of Eq. 15 and over a uniform pressure; Boussinesq
// against the field of a uniformly loaded disc (on its axis in closed form, and far away).
// The superposition integrals are GSL adaptive quadrature to 1e-12, with the near-singular
// Poisson-kernel peak of a near-surface point (width ~ z, at s = x) given as breakpoints.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "oracles/boussinesq.hpp"
#include "oracles/flamant.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/quadrature.hpp"
#include "oracles/strip_load.hpp"
#include "support/tolerance.hpp"

namespace cs::oracles {
namespace {

using cs::testing::Near;
using std::numbers::pi;

/// 29 interior points for a contact of half-width 1: a grid over the region the study models,
/// points just below the surface under and beside the contact, and points next to the edge.
std::vector<PlanePoint> interior_points() {
  std::vector<PlanePoint> points;
  for (const double x : {0.0, 0.45, -0.8, 1.6, -3.0}) {
    for (const double z : {0.2, 1.0, 3.5})
      points.push_back({x, z});
  }
  const PlanePoint near_surface_and_edge[] = {
      {0.3, 1e-3},   {-0.5, 1e-4},  {2.0, 1e-3},   {-1.5, 1e-4},  // just below the surface
      {0.999, 1e-3}, {1.001, 1e-3}, {1.0, 2e-3},   {-1.0, 1e-4},  // at the contact edge
      {0.99, 0.01},  {1.01, 0.01},  {-0.98, 0.05}, {1.05, 0.05},  // near the edge
      {0.0, 1e-5},   {7.0, 0.5},
  };
  points.insert(points.end(), std::begin(near_surface_and_edge), std::end(near_surface_and_edge));
  return points;
}

/// The stress at `at` of the Flamant line loads pressure(s) ds over |s| < half_width.
/// `p` is the pressure scale, for the absolute tolerance of components that cancel.
template <typename Pressure>
PlaneStress flamant_superposition(Pressure pressure, double half_width, double p, PlanePoint at) {
  // Breakpoints: the contact edges and the kernel peak s = x +- z, where it lies inside.
  std::vector<double> points{-half_width, half_width};
  for (const double s : {at.x - at.z, at.x, at.x + at.z}) {
    if (s > -half_width && s < half_width)
      points.push_back(s);
  }
  std::sort(points.begin(), points.end());
  const QuadratureTolerance tol{.abs = 1e-13 * p, .rel = 1e-12};
  auto component = [&](auto member) {
    return integrate_with_breakpoints(
               [&](double s) {
                 return pressure(s) * flamant_stress({.P = 1.0}, {at.x - s, at.z}).*member;
               },
               points, tol)
        .value;
  };
  return {component(&PlaneStress::sigma_x), component(&PlaneStress::sigma_z),
          component(&PlaneStress::tau_xz)};
}

// The bar: 1e-8 relative; the absolute floor 1e-11 p (a hundred times the quadrature's
// absolute tolerance) covers the components that vanish by symmetry (tau_xz on x = 0) or
// nearly (just below the surface), where the quadrature returns its own noise.
constexpr double kRel = 1e-8;
constexpr double kAbsOverP = 1e-11;

/// Compares the three components; returns the largest relative difference seen.
double expect_same_stress(const PlaneStress& closed_form, const PlaneStress& superposed, double p,
                          PlanePoint at) {
  const cs::testing::Tolerance tol{.rel = kRel, .abs = kAbsOverP * p};
  EXPECT_TRUE(Near(closed_form.sigma_x, superposed.sigma_x, tol))
      << "sigma_x at " << at.x << ", " << at.z;
  EXPECT_TRUE(Near(closed_form.sigma_z, superposed.sigma_z, tol))
      << "sigma_z at " << at.x << ", " << at.z;
  EXPECT_TRUE(Near(closed_form.tau_xz, superposed.tau_xz, tol))
      << "tau_xz at " << at.x << ", " << at.z;
  double worst = 0.0;
  for (const auto member : {&PlaneStress::sigma_x, &PlaneStress::sigma_z, &PlaneStress::tau_xz}) {
    const double scale = std::max(std::abs(superposed.*member), kAbsOverP * p / kRel);
    worst = std::max(worst, std::abs(closed_form.*member - superposed.*member) / scale);
  }
  return worst;
}

TEST(Superposition, McEwenFieldIsTheFlamantSuperpositionOfTheHertzPressure) {
  const McEwenLoad load{.a = 1.0, .p = 2.5};
  const HertzPlaneContact contact{
      .contact_half_width_a = load.a, .p_mean = load.p, .p_max = 4.0 * load.p / pi};
  double worst = 0.0;
  for (const PlanePoint at : interior_points()) {
    const PlaneStress superposed = flamant_superposition(
        [&](double s) { return hertz_plane_pressure(contact, s); }, load.a, load.p, at);
    worst = std::max(worst, expect_same_stress(mcewen_stress(load, at), superposed, load.p, at));
  }
  std::printf("[   info   ] McEwen vs Flamant superposition: worst relative difference %.2e\n",
              worst);
}

TEST(Superposition, StripLoadFieldIsTheFlamantSuperpositionOfAUniformPressure) {
  const StripLoad load{.a = 1.0, .p = 2.5};
  double worst = 0.0;
  for (const PlanePoint at : interior_points()) {
    const PlaneStress superposed =
        flamant_superposition([&](double) { return load.p; }, load.a, load.p, at);
    worst =
        std::max(worst, expect_same_stress(strip_load_stress(load, at), superposed, load.p, at));
  }
  std::printf("[   info   ] strip vs Flamant superposition: worst relative difference %.2e\n",
              worst);
}

/// The Boussinesq fields of a pressure q on the disc s < c, at (r, z), r >= 0, z > 0: the
/// point-load field of each element q s ds dpsi, rotated from its own cylindrical frame
/// (centred on the element) into the frame of the point.
AxiStress boussinesq_disc(double q, double c, double nu, AxiPoint at) {
  // Absolute floor: 1e-13 of the point load's stress scale, for components that cancel.
  const double scale = q * c * c / (at.r * at.r + at.z * at.z);
  const QuadratureTolerance tol{.abs = 1e-13 * scale, .rel = 1e-11};
  auto component = [&](int which) {
    auto over_s = [&](double s) {
      auto over_psi = [&](double psi) {
        const double dx = at.r - s * std::cos(psi);
        const double dy = -s * std::sin(psi);
        const double distance = std::hypot(dx, dy);
        const double cos_b = distance > 0.0 ? dx / distance : 1.0;
        const double sin_b = distance > 0.0 ? dy / distance : 0.0;
        const AxiStress e = boussinesq_stress({.P = 1.0, .nu = nu}, {distance, at.z});
        switch (which) {
          case 0:
            return e.sigma_r * cos_b * cos_b + e.sigma_theta * sin_b * sin_b;
          case 1:
            return e.sigma_z;
          case 2:
            return e.sigma_r * sin_b * sin_b + e.sigma_theta * cos_b * cos_b;
          default:
            return e.tau_rz * cos_b;
        }
      };
      // Symmetric in psi: twice the half disc.
      return 2.0 * s *
             integrate(over_psi, 0.0, pi, {.abs = tol.abs / (c * q), .rel = tol.rel}).value;
    };
    return q * integrate(over_s, 0.0, c, tol).value;
  };
  return {component(0), component(1), component(2), component(3)};
}

TEST(Superposition, BoussinesqIntegratedOverADiscGivesTheClosedFormOnItsAxis) {
  // Uniform pressure q on a disc of radius c, on its axis (Timoshenko and Goodier; Johnson
  // Ch. 3): sigma_z = -q (1 - z^3 / R^3), sigma_r = sigma_theta = -(q/2) ((1 + 2nu)
  // - 2 (1 + nu) z / R + z^3 / R^3), R = (c^2 + z^2)^(1/2). Integrated over rings, where a
  // ring's on-axis sigma_r is the mean of the point load's sigma_r and sigma_theta: this pins
  // the (1 - 2nu) terms and the hoop stress, which equilibrium alone does not.
  const double q = 3.0;
  const double c = 0.8;
  const QuadratureTolerance tol{.abs = 0.0, .rel = 1e-12};
  for (const double nu : {0.0, 0.25, 0.45}) {
    for (const double z : {0.01, 0.3, 1.0, 5.0}) {
      const double R = std::hypot(c, z);
      const double zr3 = std::pow(z / R, 3);
      const double sigma_z = -q * (1.0 - zr3);
      const double sigma_r = -0.5 * q * ((1.0 + 2.0 * nu) - 2.0 * (1.0 + nu) * z / R + zr3);
      const auto ring_sz = integrate(
          [&](double s) {
            return q * 2.0 * pi * s * boussinesq_stress({.P = 1.0, .nu = nu}, {s, z}).sigma_z;
          },
          0.0, c, tol);
      const auto ring_sr = integrate(
          [&](double s) {
            const AxiStress e = boussinesq_stress({.P = 1.0, .nu = nu}, {s, z});
            return q * 2.0 * pi * s * 0.5 * (e.sigma_r + e.sigma_theta);
          },
          0.0, c, tol);
      // Quadrature to 1e-12; 1e-9 relative leaves room for the cancellation in 1 - z^3/R^3
      // deep below the disc (z = 5c: the closed form loses 2 digits).
      EXPECT_TRUE(Near(ring_sz.value, sigma_z, {.rel = 1e-9, .abs = 1e-14 * q}))
          << "nu = " << nu << ", z = " << z;
      EXPECT_TRUE(Near(ring_sr.value, sigma_r, {.rel = 1e-9, .abs = 1e-14 * q}))
          << "nu = " << nu << ", z = " << z;
    }
  }
}

TEST(Superposition, SmallUniformlyLoadedDiscFarAwayActsAsBoussinesqPointLoad) {
  // A disc of radius c carrying P = q pi c^2 differs from the point load by its second moment:
  // O((c / rho)^2) relative at distance rho. The error must be small and shrink fourfold when
  // the disc radius halves, in all four components (the hoop stress through the rotation of
  // off-axis elements into the point's frame).
  const double nu = 0.3;
  const double P = 2.0;
  const AxiPoint far_points[] = {{1.0, 0.5}, {0.3, 1.0}, {2.0, 0.2}, {0.0, 1.5}};
  for (const AxiPoint at : far_points) {
    const double rho = std::hypot(at.r, at.z);
    const AxiStress point = boussinesq_stress({.P = P, .nu = nu}, at);
    double previous_error[4] = {0, 0, 0, 0};
    for (const double c_over_rho : {0.04, 0.02}) {
      const double c = c_over_rho * rho;
      const AxiStress disc = boussinesq_disc(P / (pi * c * c), c, nu, at);
      const double scale = std::max({std::abs(point.sigma_r), std::abs(point.sigma_z),
                                     std::abs(point.sigma_theta), std::abs(point.tau_rz)});
      const double error[4] = {std::abs(disc.sigma_r - point.sigma_r) / scale,
                               std::abs(disc.sigma_z - point.sigma_z) / scale,
                               std::abs(disc.sigma_theta - point.sigma_theta) / scale,
                               std::abs(disc.tau_rz - point.tau_rz) / scale};
      for (int k = 0; k < 4; ++k) {
        // Second-moment correction: a few (c/rho)^2 at most.
        EXPECT_LT(error[k], 5.0 * c_over_rho * c_over_rho)
            << "component " << k << " at r = " << at.r << ", z = " << at.z;
        if (previous_error[k] > 1e-9) {  // a component that vanishes by symmetry has no rate
          const double ratio = previous_error[k] / error[k];
          EXPECT_GT(ratio, 3.5) << "component " << k << " at r = " << at.r << ", z = " << at.z;
          EXPECT_LT(ratio, 4.5) << "component " << k << " at r = " << at.r << ", z = " << at.z;
        }
        previous_error[k] = error[k];
      }
    }
  }
}

}  // namespace
}  // namespace cs::oracles

// Every interior field satisfies the field equations of elasticity without body force and the
// boundary conditions of its surface:
// - equilibrium, both equations (with the hoop terms for the axisymmetric fields), by
//   fourth-order central differences;
// - compatibility of the strains: for plane strain the trace sigma_x + sigma_z is harmonic; for
//   the axisymmetric fields eps_r = d(r eps_theta)/dr and d(eps_z)/dr = d(gamma_rz)/dz -
//   r d2(eps_theta)/dz2 (from u_r = r eps_theta), which pin the nu-dependent terms;
// - the surface z = 0 traction free outside the contact, frictionless (tau = 0) under it, and
//   the fields continuous onto it.
// Residuals are made dimensionless with the point's stress scale and its distance L to the
// surface, where every singular point lies.

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "oracles/boussinesq.hpp"
#include "oracles/flamant.hpp"
#include "oracles/flamant_tangential.hpp"
#include "oracles/frictional_patch_test.hpp"
#include "oracles/hertz_tangential_traction.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/patch_test.hpp"
#include "oracles/strip_load.hpp"
#include "support/tolerance.hpp"

namespace cs::oracles {
namespace {

using cs::testing::Near;

using PlaneField = std::function<PlaneStress(PlanePoint)>;
using AxiField = std::function<AxiStress(AxiPoint)>;

/// Fourth-order central first derivative of f at t with step h.
template <typename F>
double d1(F f, double t, double h) {
  return (f(t - 2 * h) - 8 * f(t - h) + 8 * f(t + h) - f(t + 2 * h)) / (12 * h);
}

/// Fourth-order central second derivative of f at t with step h.
template <typename F>
double d2(F f, double t, double h) {
  return (-f(t - 2 * h) + 16 * f(t - h) - 30 * f(t) + 16 * f(t + h) - f(t + 2 * h)) / (12 * h * h);
}

// Steps relative to L: 1e-3 L for first derivatives (truncation ~1e-12, rounding ~1e-13 of the
// scale), 1e-2 L for second derivatives (truncation ~1e-8, rounding ~1e-11).
constexpr double kStep1 = 1e-3;
constexpr double kStep2 = 1e-2;
// Dimensionless residual bars: about a hundred times the observed worst (1e-11 for first
// derivatives, 1e-8 for the second-derivative compatibility); a sign error, a wrong factor or
// a wrong nu term gives O(1e-2) or more.
constexpr double kEquilibriumBar = 1e-9;
constexpr double kCompatibilityBar = 1e-6;

struct NamedPlaneField {
  std::string name;
  PlaneField field;
};

std::vector<NamedPlaneField> plane_fields() {
  return {
      {"flamant", [](PlanePoint p) { return flamant_stress({.P = 2.0}, p); }},
      {"mcewen", [](PlanePoint p) { return mcewen_stress({.a = 1.0, .p = 2.0}, p); }},
      {"strip", [](PlanePoint p) { return strip_load_stress({.a = 1.0, .p = 2.0}, p); }},
      {"patch", [](PlanePoint p) { return patch_test_plane_stress({.p = 2.0}, p); }},
      {"flamant tangential", [](PlanePoint p) { return flamant_tangential_stress({.Q = 2.0}, p); }},
      {"hertz tangential",
       [](PlanePoint p) { return hertz_tangential_traction_stress({.a = 1.0, .q0 = 2.0}, p); }},
      {"cattaneo-mindlin (McEwen + two tangential fields, c = 0.6 a)",
       [](PlanePoint p) {
         const PlaneStress n = mcewen_stress({.a = 1.0, .p = 0.25 * std::numbers::pi * 2.0}, p);
         const PlaneStress t1 = hertz_tangential_traction_stress({.a = 1.0, .q0 = 0.8}, p);
         const PlaneStress t2 = hertz_tangential_traction_stress({.a = 0.6, .q0 = -0.48}, p);
         return PlaneStress{n.sigma_x + t1.sigma_x + t2.sigma_x,
                            n.sigma_z + t1.sigma_z + t2.sigma_z, n.tau_xz + t1.tau_xz + t2.tau_xz};
       }},
      {"frictional patch, stick",
       [](PlanePoint p) {
         return frictional_patch_stick_stress({.p = 2.0, .tau = 0.5, .mu = 0.3}, p);
       }},
  };
}

std::vector<PlanePoint> plane_points() {
  std::vector<PlanePoint> points;
  for (const double x : {-2.2, -0.95, 0.0, 0.4, 0.97, 1.03, 2.5}) {
    for (const double z : {0.03, 0.4, 1.7})
      points.push_back({x, z});
  }
  return points;
}

double stress_scale(const PlaneStress& s) {
  return std::max({std::abs(s.sigma_x), std::abs(s.sigma_z), std::abs(s.tau_xz)});
}

/// The stress scale around a point at depth L: the largest component at the point and at
/// (x +- L, z), so that a field vanishing at the point by symmetry (the tangential Flamant
/// field on x = 0) still has the scale of its gradients.
double local_stress_scale(const PlaneField& field, PlanePoint at) {
  const double L = at.z;
  return std::max({stress_scale(field(at)), stress_scale(field({at.x - L, at.z})),
                   stress_scale(field({at.x + L, at.z}))});
}

TEST(FieldEquations, PlaneFieldsAreInEquilibrium) {
  for (const auto& [name, field] : plane_fields()) {
    for (const PlanePoint at : plane_points()) {
      const double L = at.z;
      const double h = kStep1 * L;
      auto along_x = [&](auto member) {
        return [&, member](double x) { return field({x, at.z}).*member; };
      };
      auto along_z = [&](auto member) {
        return [&, member](double z) { return field({at.x, z}).*member; };
      };
      const double div_x =
          d1(along_x(&PlaneStress::sigma_x), at.x, h) + d1(along_z(&PlaneStress::tau_xz), at.z, h);
      const double div_z =
          d1(along_x(&PlaneStress::tau_xz), at.x, h) + d1(along_z(&PlaneStress::sigma_z), at.z, h);
      const double scale = local_stress_scale(field, at) / L;
      EXPECT_LT(std::abs(div_x) / scale, kEquilibriumBar) << name << " at " << at.x << ", " << at.z;
      EXPECT_LT(std::abs(div_z) / scale, kEquilibriumBar) << name << " at " << at.x << ", " << at.z;
    }
  }
}

TEST(FieldEquations, PlaneFieldsAreCompatible) {
  // Plane strain without body force: Laplacian(sigma_x + sigma_z) = 0.
  for (const auto& [name, field] : plane_fields()) {
    for (const PlanePoint at : plane_points()) {
      const double L = at.z;
      const double h = kStep2 * L;
      auto trace_x = [&](double x) {
        const PlaneStress s = field({x, at.z});
        return s.sigma_x + s.sigma_z;
      };
      auto trace_z = [&](double z) {
        const PlaneStress s = field({at.x, z});
        return s.sigma_x + s.sigma_z;
      };
      const double laplacian = d2(trace_x, at.x, h) + d2(trace_z, at.z, h);
      const double scale = local_stress_scale(field, at) / (L * L);
      EXPECT_LT(std::abs(laplacian) / scale, kCompatibilityBar)
          << name << " at " << at.x << ", " << at.z;
    }
  }
}

struct NamedAxiField {
  std::string name;
  double nu;
  AxiField field;
};

std::vector<NamedAxiField> axi_fields() {
  std::vector<NamedAxiField> fields;
  for (const double nu : {0.0, 0.25, 0.45}) {
    fields.push_back({"boussinesq nu = " + std::to_string(nu), nu,
                      [nu](AxiPoint p) { return boussinesq_stress({.P = 3.0, .nu = nu}, p); }});
  }
  fields.push_back({"patch", 0.3, [](AxiPoint p) { return patch_test_axi_stress({.p = 2.0}, p); }});
  return fields;
}

std::vector<AxiPoint> axi_points() {
  std::vector<AxiPoint> points;
  for (const double r : {0.1, 0.5, 1.2, 3.0}) {
    for (const double z : {0.05, 0.5, 2.0})
      points.push_back({r, z});
  }
  return points;
}

double stress_scale(const AxiStress& s) {
  return std::max(
      {std::abs(s.sigma_r), std::abs(s.sigma_z), std::abs(s.sigma_theta), std::abs(s.tau_rz)});
}

TEST(FieldEquations, AxisymmetricFieldsAreInEquilibrium) {
  for (const auto& [name, nu, field] : axi_fields()) {
    for (const AxiPoint at : axi_points()) {
      const double L = std::min(at.r, at.z);
      const double h = kStep1 * L;
      auto along_r = [&](auto member) {
        return [&, member](double r) { return field({r, at.z}).*member; };
      };
      auto along_z = [&](auto member) {
        return [&, member](double z) { return field({at.r, z}).*member; };
      };
      const AxiStress s = field(at);
      const double div_r = d1(along_r(&AxiStress::sigma_r), at.r, h) +
                           d1(along_z(&AxiStress::tau_rz), at.z, h) +
                           (s.sigma_r - s.sigma_theta) / at.r;
      const double div_z = d1(along_r(&AxiStress::tau_rz), at.r, h) +
                           d1(along_z(&AxiStress::sigma_z), at.z, h) + s.tau_rz / at.r;
      const double scale = stress_scale(s) / L;
      EXPECT_LT(std::abs(div_r) / scale, kEquilibriumBar) << name << " at " << at.r << ", " << at.z;
      EXPECT_LT(std::abs(div_z) / scale, kEquilibriumBar) << name << " at " << at.r << ", " << at.z;
    }
  }
}

TEST(FieldEquations, AxisymmetricFieldsAreCompatible) {
  for (const auto& [name, nu, field] : axi_fields()) {
    // Hooke's law with E = 1 (compatibility is homogeneous in 1/E).
    auto eps_r = [&](AxiPoint p) {
      const AxiStress s = field(p);
      return s.sigma_r - nu * (s.sigma_theta + s.sigma_z);
    };
    auto eps_theta = [&](AxiPoint p) {
      const AxiStress s = field(p);
      return s.sigma_theta - nu * (s.sigma_r + s.sigma_z);
    };
    auto eps_z = [&](AxiPoint p) {
      const AxiStress s = field(p);
      return s.sigma_z - nu * (s.sigma_r + s.sigma_theta);
    };
    auto gamma_rz = [&](AxiPoint p) { return 2.0 * (1.0 + nu) * field(p).tau_rz; };
    for (const AxiPoint at : axi_points()) {
      const double L = std::min(at.r, at.z);
      const double scale = stress_scale(field(at)) * std::max(1.0, at.r / L);
      // eps_r = d(r eps_theta)/dr = eps_theta + r d(eps_theta)/dr
      const double h1 = kStep1 * L;
      const double first = eps_r(at) - eps_theta(at) -
                           at.r * d1(
                                      [&](double r) {
                                        return eps_theta({r, at.z});
                                      },
                                      at.r, h1);
      EXPECT_LT(std::abs(first) / scale, kEquilibriumBar) << name << " at " << at.r << ", " << at.z;
      // d(eps_z)/dr = d(gamma_rz)/dz - r d2(eps_theta)/dz2
      const double h2 = kStep2 * L;
      const double second = d1(
                                [&](double r) {
                                  return eps_z({r, at.z});
                                },
                                at.r, h1) -
                            d1(
                                [&](double z) {
                                  return gamma_rz({at.r, z});
                                },
                                at.z, h1) +
                            at.r * d2(
                                       [&](double z) {
                                         return eps_theta({at.r, z});
                                       },
                                       at.z, h2);
      EXPECT_LT(std::abs(second) * L / scale, kCompatibilityBar)
          << name << " at " << at.r << ", " << at.z;
    }
  }
}

// Exact zeros on the surface, and continuity onto it from z = 1e-9: at a distance d from the
// nearest edge or load point the fields are within O(p z / d) of their surface values (bar:
// ten times that).
constexpr cs::testing::Tolerance kExactZero{.rel = 0.0, .abs = 1e-15};
constexpr double kNearSurfaceZ = 1e-9;
cs::testing::Tolerance continuity(double p, double d) {
  return {.rel = 0.0, .abs = 10.0 * p * kNearSurfaceZ / d};
}

TEST(FieldEquations, PlaneSurfacesAreTractionFreeOutsideTheLoadAndFrictionlessUnderIt) {
  const double p = 2.0;
  const McEwenLoad hertz{.a = 1.0, .p = p};
  const StripLoad strip{.a = 1.0, .p = p};
  for (const double x : {-3.0, -1.2, -1.0001, 1.0001, 1.5, 4.0}) {
    for (const double z : {0.0, kNearSurfaceZ}) {
      const auto tol = z == 0.0 ? kExactZero : continuity(p, std::abs(x) - 1.0);
      for (const PlaneStress s : {flamant_stress({.P = p}, {x, z}), mcewen_stress(hertz, {x, z}),
                                  strip_load_stress(strip, {x, z})}) {
        EXPECT_TRUE(Near(s.sigma_z, 0.0, tol)) << "x = " << x << ", z = " << z;
        EXPECT_TRUE(Near(s.tau_xz, 0.0, tol)) << "x = " << x << ", z = " << z;
      }
    }
  }
  for (const double x : {-0.999, -0.5, 0.0, 0.3, 0.9999}) {
    for (const double z : {0.0, kNearSurfaceZ}) {
      const auto tol = z == 0.0 ? kExactZero : continuity(p, 1.0 - std::abs(x));
      EXPECT_TRUE(Near(mcewen_stress(hertz, {x, z}).tau_xz, 0.0, tol)) << x;
      EXPECT_TRUE(Near(strip_load_stress(strip, {x, z}).tau_xz, 0.0, tol)) << x;
      // Under the strip the normal traction is the applied pressure.
      const auto pressure_tol = z == 0.0 ? cs::testing::Tolerance{.rel = 1e-15} : tol;
      EXPECT_TRUE(Near(strip_load_stress(strip, {x, z}).sigma_z, -p, pressure_tol)) << x;
      EXPECT_TRUE(Near(strip_load_stress(strip, {x, z}).sigma_x, -p, pressure_tol)) << x;
    }
  }
}

TEST(FieldEquations, BoussinesqSurfaceIsTractionFreeAwayFromTheLoad) {
  for (const double nu : {0.0, 0.3}) {
    const BoussinesqLoad load{.P = 5.0, .nu = nu};
    for (const double r : {0.01, 0.7, 3.0}) {
      const AxiStress s = boussinesq_stress(load, {r, 0.0});
      EXPECT_TRUE(Near(s.sigma_z, 0.0, kExactZero)) << r;
      EXPECT_TRUE(Near(s.tau_rz, 0.0, kExactZero)) << r;
      // ... and on the surface sigma_theta = -sigma_r = -(1 - 2nu) P / (2 pi r^2) (Johnson).
      const double sigma_r = (1.0 - 2.0 * nu) * load.P / (2.0 * std::numbers::pi * r * r);
      EXPECT_TRUE(Near(s.sigma_r, sigma_r, {.rel = 1e-14, .abs = 0.0})) << r;
      EXPECT_TRUE(Near(s.sigma_theta, -sigma_r, {.rel = 1e-14, .abs = 0.0})) << r;
      const AxiStress below = boussinesq_stress(load, {r, kNearSurfaceZ * r});
      EXPECT_TRUE(Near(below.sigma_z, 0.0, {.rel = 0.0, .abs = 1e-7 * std::abs(sigma_r) + 1e-15}));
      EXPECT_TRUE(Near(below.tau_rz, 0.0, {.rel = 0.0, .abs = 1e-7 * std::abs(sigma_r) + 1e-15}));
    }
  }
}

TEST(FieldEquations, BoussinesqOnTheAxisHasEqualRadialAndHoopStress) {
  // Axisymmetry: sigma_r = sigma_theta and tau_rz = 0 on r = 0, finite there.
  const BoussinesqLoad load{.P = 5.0, .nu = 0.2};
  for (const double z : {0.1, 1.0, 10.0}) {
    const AxiStress s = boussinesq_stress(load, {0.0, z});
    EXPECT_TRUE(Near(s.sigma_r, s.sigma_theta, {.rel = 1e-14}));
    EXPECT_TRUE(Near(s.tau_rz, 0.0, kExactZero));
    EXPECT_TRUE(Near(s.sigma_z, -3.0 * load.P / (2.0 * std::numbers::pi * z * z), {.rel = 1e-14}));
    // Continuous onto the axis.
    const AxiStress near_axis = boussinesq_stress(load, {1e-7 * z, z});
    EXPECT_TRUE(Near(near_axis.sigma_r, s.sigma_r, {.rel = 1e-12}));
    EXPECT_TRUE(Near(near_axis.sigma_theta, s.sigma_theta, {.rel = 1e-12}));
  }
}

}  // namespace
}  // namespace cs::oracles

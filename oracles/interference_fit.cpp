#include "oracles/interference_fit.hpp"

#include <cmath>
#include <string>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {
namespace {

constexpr double kMaxInterferenceOverRadius = 1e-2;

void require_material(const char* where, const char* which, const LameMaterial& m) {
  require_positive(where, std::string("Young's modulus E of the ") + which, m.E);
  require_poisson_ratio(where, m.nu);
}

/// Validates the fit; returns beta = b / c (0 for c = inf).
double validated_beta(const char* where, const InterferenceFit& fit) {
  require_positive(where, "interface radius b", fit.b);
  if (!(fit.c > fit.b)) {
    throw InvalidInput(std::string(where) + ": outer radius c = " + format_value(fit.c) +
                       " must exceed the interface radius b = " + format_value(fit.b));
  }
  require_positive(where, "interference delta", fit.delta);
  if (!(fit.delta / fit.b <= kMaxInterferenceOverRadius)) {
    throw InvalidInput(std::string(where) +
                       ": interference delta/b = " + format_value(fit.delta / fit.b) +
                       " exceeds 1e-2, the small-strain limit of the oracle (Lame's linear "
                       "solution on the undeformed radii)");
  }
  require_material(where, "inner body", fit.inner);
  require_material(where, "outer body", fit.outer);
  return std::isinf(fit.c) ? 0.0 : fit.b / fit.c;
}

/// (c - r) / (c - b) * f: the factor that makes sigma_r vanish exactly at r = c (1 for c = inf).
double towards_outer_surface(const InterferenceFit& fit, double r) {
  return std::isinf(fit.c) ? 1.0 : (fit.c - r) / (fit.c - fit.b);
}

void require_radius(const char* where, const InterferenceFit& fit, FitBody body, double r) {
  if (body != FitBody::kInner && body != FitBody::kOuter)
    throw InvalidInput(std::string(where) + ": unknown FitBody");
  const bool inner = body == FitBody::kInner;
  const bool inside = inner ? (r >= 0.0 && r <= fit.b) : (r >= fit.b && r <= fit.c);
  if (!inside || !std::isfinite(r)) {
    throw InvalidInput(std::string(where) + ": radius " + format_value(r) +
                       (inner ? " outside the inner body [0, b] = [0, "
                              : " outside the outer body [b, c] = [" + format_value(fit.b) + ", ") +
                       format_value(inner ? fit.b : fit.c) + "]");
  }
}

}  // namespace

double interference_fit_cylinder_pressure(const InterferenceFit& fit) {
  const double beta = validated_beta("interference_fit_cylinder_pressure", fit);
  const double one_minus_beta2 = (1.0 - beta) * (1.0 + beta);
  const double nu1 = fit.inner.nu;
  const double nu2 = fit.outer.nu;
  // Compliances in units of 1/E2: no overflow of 1/E for extreme moduli.
  const double ring = (1.0 + nu2) * (1.0 + (1.0 - 2.0 * nu2) * beta * beta) / one_minus_beta2;
  const double shaft = (1.0 + nu1) * (1.0 - 2.0 * nu1) * (fit.outer.E / fit.inner.E);
  return fit.delta / fit.b * fit.outer.E / (ring + shaft);
}

CylinderFitState interference_fit_cylinder_state(const InterferenceFit& fit, FitBody body,
                                                 double r) {
  constexpr const char* kWhere = "interference_fit_cylinder_state";
  const double p = interference_fit_cylinder_pressure(fit);
  const double beta = validated_beta(kWhere, fit);
  require_radius(kWhere, fit, body, r);
  if (body == FitBody::kInner) {
    const LameMaterial& m = fit.inner;
    return {-p, -p, -2.0 * m.nu * p, -(1.0 + m.nu) * (1.0 - 2.0 * m.nu) * p / m.E * r};
  }
  const LameMaterial& m = fit.outer;
  const double b_over_r = fit.b / r;
  const double r_over_c = std::isinf(fit.c) ? 0.0 : r / fit.c;
  const double one_minus_beta2 = (1.0 - beta) * (1.0 + beta);
  // sigma_r = -p (b/r)^2 (1 - r^2/c^2) / (1 - beta^2), sigma_theta = p (beta^2 + (b/r)^2) / (...)
  const double sigma_r =
      -p * b_over_r * b_over_r * towards_outer_surface(fit, r) * ((1.0 + r_over_c) / (1.0 + beta));
  const double sigma_theta = p * (beta * beta + b_over_r * b_over_r) / one_minus_beta2;
  // u = ((1 + nu)/E) ((1 - 2nu) A r + B/r), A = p beta^2 / (1 - beta^2), B = p b^2 / (1 - beta^2).
  const double u_r = (1.0 + m.nu) / m.E * p / one_minus_beta2 *
                     ((1.0 - 2.0 * m.nu) * beta * beta * r + fit.b * b_over_r);
  return {sigma_r, sigma_theta, m.nu * (sigma_r + sigma_theta), u_r};
}

PlaneStress interference_fit_cylinder_stress(const InterferenceFit& fit, FitBody body,
                                             PlanePoint at) {
  constexpr const char* kWhere = "interference_fit_cylinder_stress";
  require_finite(kWhere, "position x", at.x);
  require_finite(kWhere, "position z", at.z);
  const double r = std::hypot(at.x, at.z);
  const CylinderFitState s = interference_fit_cylinder_state(fit, body, r);
  const double cos_t = r > 0.0 ? at.x / r : 1.0;
  const double sin_t = r > 0.0 ? at.z / r : 0.0;
  return {
      .sigma_x = s.sigma_r * cos_t * cos_t + s.sigma_theta * sin_t * sin_t,
      .sigma_z = s.sigma_r * sin_t * sin_t + s.sigma_theta * cos_t * cos_t,
      .tau_xz = (s.sigma_r - s.sigma_theta) * sin_t * cos_t,
  };
}

double interference_fit_sphere_pressure(const InterferenceFit& fit) {
  const double beta = validated_beta("interference_fit_sphere_pressure", fit);
  const double one_minus_beta3 = (1.0 - beta) * (1.0 + beta + beta * beta);
  const double nu1 = fit.inner.nu;
  const double nu2 = fit.outer.nu;
  const double shell =
      ((1.0 - 2.0 * nu2) * beta * beta * beta + 0.5 * (1.0 + nu2)) / one_minus_beta3;
  const double sphere = (1.0 - 2.0 * nu1) * (fit.outer.E / fit.inner.E);
  return fit.delta / fit.b * fit.outer.E / (shell + sphere);
}

SphereFitState interference_fit_sphere_state(const InterferenceFit& fit, FitBody body, double R) {
  constexpr const char* kWhere = "interference_fit_sphere_state";
  const double p = interference_fit_sphere_pressure(fit);
  const double beta = validated_beta(kWhere, fit);
  require_radius(kWhere, fit, body, R);
  if (body == FitBody::kInner) {
    const LameMaterial& m = fit.inner;
    return {-p, -p, -(1.0 - 2.0 * m.nu) * p / m.E * R};
  }
  const LameMaterial& m = fit.outer;
  const double b_over_R = fit.b / R;
  const double b3 = b_over_R * b_over_R * b_over_R;  // (b/R)^3
  const double R_over_c = std::isinf(fit.c) ? 0.0 : R / fit.c;
  const double beta3 = beta * beta * beta;
  const double one_minus_beta3 = (1.0 - beta) * (1.0 + beta + beta * beta);
  // sigma_r = -p (b/R)^3 (1 - R^3/c^3) / (1 - beta^3), 1 - R^3/c^3 = (1 - R/c)(1 + R/c + R^2/c^2).
  const double sigma_r = -p * b3 * towards_outer_surface(fit, R) *
                         ((1.0 + R_over_c + R_over_c * R_over_c) / (1.0 + beta + beta * beta));
  const double sigma_theta = p * (beta3 + 0.5 * b3) / one_minus_beta3;
  // u = (R/E) ((1 - 2nu) A + (1 + nu) B / R^3), A = p beta^3/(1 - beta^3), B/R^3 = p (b/R)^3 /
  // (2 (1 - beta^3)).
  const double u_r =
      R / m.E * p / one_minus_beta3 * ((1.0 - 2.0 * m.nu) * beta3 + 0.5 * (1.0 + m.nu) * b3);
  return {sigma_r, sigma_theta, u_r};
}

AxiStress interference_fit_sphere_stress(const InterferenceFit& fit, FitBody body, AxiPoint at) {
  constexpr const char* kWhere = "interference_fit_sphere_stress";
  require_non_negative(kWhere, "radius r", at.r);
  require_finite(kWhere, "position z", at.z);
  const double R = std::hypot(at.r, at.z);
  const SphereFitState s = interference_fit_sphere_state(fit, body, R);
  const double sin_a = R > 0.0 ? at.r / R : 0.0;  // the angle from the z axis
  const double cos_a = R > 0.0 ? at.z / R : 1.0;
  return {
      .sigma_r = s.sigma_r * sin_a * sin_a + s.sigma_theta * cos_a * cos_a,
      .sigma_z = s.sigma_r * cos_a * cos_a + s.sigma_theta * sin_a * sin_a,
      .sigma_theta = s.sigma_theta,
      .tau_rz = (s.sigma_r - s.sigma_theta) * sin_a * cos_a,
  };
}

}  // namespace cs::oracles

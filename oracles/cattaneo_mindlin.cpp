#include "oracles/cattaneo_mindlin.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {
namespace {

/// (1 - (x/h)^2)^(1/2) for |x| < h, 0 outside, without cancellation next to the edge.
double semi_ellipse(double h, double x) {
  const double s = std::abs(x);
  if (s >= h)
    return 0.0;
  return std::sqrt((h - s) / h * (1.0 + s / h));
}

void require_contact(const char* where, const CattaneoMindlinContact& c) {
  require_positive(where, "contact half-width a", c.contact_half_width_a);
  require_positive(where, "peak pressure p0", c.p0);
  require_friction_coefficient(where, c.mu);
  if (!(c.Q_over_mu_P >= 0.0 && c.Q_over_mu_P < 1.0)) {
    throw InvalidInput(std::string(where) + ": Q/(mu P) = " + format_value(c.Q_over_mu_P) +
                       " must lie in [0, 1)");
  }
  if (!(c.stick_half_width_c > 0.0 && c.stick_half_width_c <= c.contact_half_width_a)) {
    throw InvalidInput(std::string(where) + ": stick half-width c = " +
                       format_value(c.stick_half_width_c) + " must lie in (0, a]");
  }
}

}  // namespace

CattaneoMindlinContact cattaneo_mindlin_contact(const CattaneoMindlinPlane& problem) {
  constexpr const char* kWhere = "cattaneo_mindlin_contact";
  require_positive(kWhere, "relative radius R", problem.R);
  require_positive(kWhere, "Young's modulus E", problem.E);
  require_poisson_ratio(kWhere, problem.nu);
  require_positive(kWhere, "normal load per unit length P", problem.P);
  require_friction_coefficient(kWhere, problem.mu);
  require_non_negative(kWhere, "tangential load per unit length Q", problem.Q);
  const double mu_P = problem.mu * problem.P;
  const double slip_ratio = problem.Q / mu_P;  // Q / (mu P); nan for Q = mu = 0
  if (!(slip_ratio < 1.0)) {
    throw InvalidInput(std::string(kWhere) +
                       ": Q >= mu P: the stick oracle needs Q < mu P (got Q = " +
                       format_value(problem.Q) + ", mu P = " + format_value(mu_P) + ")");
  }
  // a / R = (8 (1 - nu^2) (P/R) / (pi E))^(1/2), in dimensionless groups.
  const double a = problem.R * std::sqrt(8.0 * (1.0 - problem.nu * problem.nu) / std::numbers::pi *
                                         (problem.P / problem.R / problem.E));
  const double p0 = 2.0 / std::numbers::pi * (problem.P / a);
  if (!(a >= std::numeric_limits<double>::min()) || !std::isfinite(a) ||
      !(p0 >= std::numeric_limits<double>::min()) || !std::isfinite(p0)) {
    throw InvalidInput(std::string(kWhere) + ": R, E, P out of floating-point range (a = " +
                       format_value(a) + ", p0 = " + format_value(p0) + ")");
  }
  const double c_over_a = std::sqrt(1.0 - slip_ratio);
  const double q_peak_over_p0 = problem.mu * std::sqrt(slip_ratio);
  return {
      .contact_half_width_a = a,
      .p0 = p0,
      .p_mean = 0.25 * std::numbers::pi * p0,
      .stick_half_width_c = c_over_a * a,
      .c_over_a = c_over_a,
      .Q_over_mu_P = slip_ratio,
      .q_peak = q_peak_over_p0 * p0,
      .q_peak_over_p0 = q_peak_over_p0,
      .q_peak_over_p_mean = 4.0 / std::numbers::pi * q_peak_over_p0,
      .mu = problem.mu,
  };
}

double cattaneo_mindlin_pressure(const CattaneoMindlinContact& contact, double x) {
  constexpr const char* kWhere = "cattaneo_mindlin_pressure";
  require_contact(kWhere, contact);
  require_finite(kWhere, "position x", x);
  return contact.p0 * semi_ellipse(contact.contact_half_width_a, x);
}

double cattaneo_mindlin_shear(const CattaneoMindlinContact& contact, double x) {
  constexpr const char* kWhere = "cattaneo_mindlin_shear";
  require_contact(kWhere, contact);
  require_finite(kWhere, "position x", x);
  const double a = contact.contact_half_width_a;
  const double c = contact.stick_half_width_c;
  const double slip_traction = contact.mu * contact.p0 * semi_ellipse(a, x);
  if (std::abs(x) >= c)
    return slip_traction;
  // In the stick zone: mu p0 ((1 - x^2/a^2)^(1/2) - (c/a) (1 - x^2/c^2)^(1/2)), rationalized.
  return contact.mu * contact.p0 * contact.Q_over_mu_P /
         (semi_ellipse(a, x) + (c / a) * semi_ellipse(c, x));
}

}  // namespace cs::oracles

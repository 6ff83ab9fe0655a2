#include "oracles/hertz_plane.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {

HertzPlaneContact hertz_plane_contact(const HertzCylinder& cylinder) {
  constexpr const char* kWhere = "hertz_plane_contact";
  require_positive(kWhere, "radius R", cylinder.R);
  require_positive(kWhere, "Young's modulus E", cylinder.E);
  require_poisson_ratio(kWhere, cylinder.nu);
  require_positive(kWhere, "load per unit length P", cylinder.P);

  const double one_minus_nu2 = 1.0 - cylinder.nu * cylinder.nu;
  const double a =
      std::sqrt(4.0 * cylinder.R * one_minus_nu2 * cylinder.P / (std::numbers::pi * cylinder.E));
  const double p_mean = cylinder.P / (2.0 * a);
  const double p_max = 4.0 * p_mean / std::numbers::pi;
  if (!(a > 0.0) || !std::isfinite(a) || !(p_mean > 0.0) || !std::isfinite(p_max)) {
    throw InvalidInput(std::string(kWhere) + ": R, E, P out of floating-point range (a = " +
                       format_value(a) + ", p = " + format_value(p_mean) + ")");
  }
  return {a, p_mean, p_max};
}

double hertz_plane_pressure(const HertzPlaneContact& contact, double x) {
  constexpr const char* kWhere = "hertz_plane_pressure";
  require_positive(kWhere, "contact half-width a", contact.contact_half_width_a);
  require_positive(kWhere, "peak pressure p_max", contact.p_max);
  require_finite(kWhere, "position x", x);
  const double s = std::abs(x) / contact.contact_half_width_a;
  if (s >= 1.0)
    return 0.0;
  return contact.p_max * std::sqrt((1.0 - s) * (1.0 + s));
}

}  // namespace cs::oracles

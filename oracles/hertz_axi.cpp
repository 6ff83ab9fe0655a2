#include "oracles/hertz_axi.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {

HertzAxiContact hertz_axi_contact(const HertzSphere& sphere) {
  constexpr const char* kWhere = "hertz_axi_contact";
  require_positive(kWhere, "radius R", sphere.R);
  require_positive(kWhere, "Young's modulus E", sphere.E);
  require_poisson_ratio(kWhere, sphere.nu);
  require_positive(kWhere, "load P", sphere.P);

  const double one_minus_nu2 = 1.0 - sphere.nu * sphere.nu;
  const double a = std::cbrt(3.0 * sphere.R * one_minus_nu2 * sphere.P / (4.0 * sphere.E));
  const double p_mean = sphere.P / (std::numbers::pi * a * a);
  const double p_max = 1.5 * p_mean;
  if (!(a > 0.0) || !std::isfinite(a) || !(p_mean > 0.0) || !std::isfinite(p_max)) {
    throw InvalidInput(std::string(kWhere) + ": R, E, P out of floating-point range (a = " +
                       format_value(a) + ", p = " + format_value(p_mean) + ")");
  }
  return {a, p_mean, p_max};
}

double hertz_axi_pressure(const HertzAxiContact& contact, double r) {
  constexpr const char* kWhere = "hertz_axi_pressure";
  require_positive(kWhere, "contact radius a", contact.contact_radius_a);
  require_positive(kWhere, "peak pressure p_max", contact.p_max);
  require_non_negative(kWhere, "radius r", r);
  const double s = r / contact.contact_radius_a;
  if (s >= 1.0)
    return 0.0;
  return contact.p_max * std::sqrt((1.0 - s) * (1.0 + s));
}

}  // namespace cs::oracles

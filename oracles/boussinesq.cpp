#include "oracles/boussinesq.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"
#include "oracles/length_scale.hpp"

namespace cs::oracles {

AxiStress boussinesq_stress(const BoussinesqLoad& load, AxiPoint at) {
  constexpr const char* kWhere = "boussinesq_stress";
  require_positive(kWhere, "load P", load.P);
  require_poisson_ratio(kWhere, load.nu);
  require_non_negative(kWhere, "radius r", at.r);
  require_in_half_space(kWhere, at.z);
  if (at.r == 0.0 && at.z == 0.0) {
    throw InvalidInput(
        std::string(kWhere) +
        ": the point (r, z) = (0, 0) is the load point, where the field is singular");
  }
  // Lengths in units of L ~ max(r, z): the direction cosines are exact to rounding whatever
  // the magnitude of (r, z).
  const LengthScale L = length_scale({at.r, at.z});
  const double r_hat = L.of(at.r);
  const double z_hat = L.of(at.z);
  const double rho_hat = std::hypot(r_hat, z_hat);  // in [1, 2^(3/2))
  const double cr = r_hat / rho_hat;                // r / rho
  const double cz = z_hat / rho_hat;                // z / rho
  // P / (2 pi rho^2), scaled step by step: underflows to 0 far away, overflows only next to
  // the load point.
  const double scale =
      L.per_unit(L.per_unit(load.P / (2.0 * std::numbers::pi))) / (rho_hat * rho_hat);
  const double one_minus_2nu = 1.0 - 2.0 * load.nu;
  const double radial_term = 1.0 / (1.0 + cz);  // (rho^2 / r^2) (1 - z / rho)
  const AxiStress s{
      .sigma_r = scale * (one_minus_2nu * radial_term - 3.0 * cr * cr * cz),
      .sigma_z = -3.0 * scale * cz * cz * cz,
      .sigma_theta = -scale * one_minus_2nu * (radial_term - cz),
      .tau_rz = -3.0 * scale * cr * cz * cz,
  };
  if (!std::isfinite(s.sigma_r) || !std::isfinite(s.sigma_z) || !std::isfinite(s.sigma_theta) ||
      !std::isfinite(s.tau_rz)) {
    throw InvalidInput(std::string(kWhere) + ": the point (r, z) = (" + format_value(at.r) + ", " +
                       format_value(at.z) +
                       ") is so close to the load point that the stress overflows");
  }
  return s;
}

}  // namespace cs::oracles

#include "oracles/boussinesq.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {

AxiStress boussinesq_stress(const BoussinesqLoad& load, AxiPoint at) {
  constexpr const char* kWhere = "boussinesq_stress";
  require_positive(kWhere, "load P", load.P);
  require_poisson_ratio(kWhere, load.nu);
  require_non_negative(kWhere, "radius r", at.r);
  require_in_half_space(kWhere, at.z);
  const double r = at.r;
  const double z = at.z;
  const double rho = std::hypot(r, z);
  if (rho == 0.0) {
    throw InvalidInput(
        std::string(kWhere) +
        ": the point (r, z) = (0, 0) is the load point, where the field is singular");
  }
  const double c = load.P / (2.0 * std::numbers::pi);
  const double rho2 = rho * rho;
  const double rho5 = rho2 * rho2 * rho;
  const double one_minus_2nu = 1.0 - 2.0 * load.nu;
  const double radial_term = 1.0 / (rho * (rho + z));  // (1 / r^2) (1 - z / rho)
  return {
      .sigma_r = c * (one_minus_2nu * radial_term - 3.0 * r * r * z / rho5),
      .sigma_z = -3.0 * c * z * z * z / rho5,
      .sigma_theta = -c * one_minus_2nu * (radial_term - z / (rho2 * rho)),
      .tau_rz = -3.0 * c * r * z * z / rho5,
  };
}

}  // namespace cs::oracles

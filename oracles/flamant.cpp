#include "oracles/flamant.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {

PlaneStress flamant_stress(const FlamantLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "flamant_stress";
  require_positive(kWhere, "load per unit length P", load.P);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);
  const double x = at.x;
  const double z = at.z;
  const double r2 = x * x + z * z;
  if (r2 == 0.0) {
    throw InvalidInput(
        std::string(kWhere) +
        ": the point (x, z) = (0, 0) is the load point, where the field is singular");
  }
  // The radial stress sigma_rr = -(2P / pi) z / r^2, projected on (e_x, e_z).
  const double sigma_rr_over_r2 = -2.0 * load.P / std::numbers::pi * z / (r2 * r2);
  return {
      .sigma_x = sigma_rr_over_r2 * x * x,
      .sigma_z = sigma_rr_over_r2 * z * z,
      .tau_xz = sigma_rr_over_r2 * x * z,
  };
}

}  // namespace cs::oracles

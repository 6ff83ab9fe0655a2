#include "oracles/flamant_tangential.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"
#include "oracles/length_scale.hpp"

namespace cs::oracles {

PlaneStress flamant_tangential_stress(const FlamantTangentialLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "flamant_tangential_stress";
  require_finite(kWhere, "tangential load per unit length Q", load.Q);
  if (load.Q == 0.0)
    throw InvalidInput(std::string(kWhere) + ": tangential load Q must be non-zero (got 0)");
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);
  if (at.x == 0.0 && at.z == 0.0) {
    throw InvalidInput(
        std::string(kWhere) +
        ": the point (x, z) = (0, 0) is the load point, where the field is singular");
  }
  const LengthScale L = length_scale({at.x, at.z});
  const double x = L.of(at.x);
  const double z = L.of(at.z);
  const double r2 = x * x + z * z;  // in [1, 8)
  // The radial stress sigma_rr = -(2Q / pi) x / r^2, projected on (e_x, e_z).
  const double sigma_rr_over_r2 = L.per_unit(-2.0 * load.Q / std::numbers::pi) * (x / (r2 * r2));
  const PlaneStress s{
      .sigma_x = sigma_rr_over_r2 * x * x,
      .sigma_z = sigma_rr_over_r2 * z * z,
      .tau_xz = sigma_rr_over_r2 * x * z,
  };
  if (!std::isfinite(s.sigma_x) || !std::isfinite(s.sigma_z) || !std::isfinite(s.tau_xz)) {
    throw InvalidInput(std::string(kWhere) + ": the point (x, z) = (" + format_value(at.x) + ", " +
                       format_value(at.z) +
                       ") is so close to the load point that the stress overflows");
  }
  return s;
}

}  // namespace cs::oracles

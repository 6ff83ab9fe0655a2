#include "oracles/flamant.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"
#include "oracles/length_scale.hpp"

namespace cs::oracles {

PlaneStress radial_line_load_stress(const char* where, double F, LineLoadDirection direction,
                                    PlanePoint at) {
  require_finite(where, "line load per unit length", F);
  require_finite(where, "position x", at.x);
  require_in_half_space(where, at.z);
  if (at.x == 0.0 && at.z == 0.0) {
    throw InvalidInput(
        std::string(where) +
        ": the point (x, z) = (0, 0) is the load point, where the field is singular");
  }
  // Lengths in units of L = max(|x|, z), so that r^4 neither over- nor underflows.
  const LengthScale L = length_scale({at.x, at.z});
  const double x = L.of(at.x);
  const double z = L.of(at.z);
  const double r2 = x * x + z * z;                                      // in [1, 8)
  const double along = direction == LineLoadDirection::normal ? z : x;  // (d . e_r) r
  const double sigma_rr_over_r2 = L.per_unit(-2.0 * F / std::numbers::pi) * (along / (r2 * r2));
  const PlaneStress s{
      .sigma_x = sigma_rr_over_r2 * x * x,
      .sigma_z = sigma_rr_over_r2 * z * z,
      .tau_xz = sigma_rr_over_r2 * x * z,
  };
  if (!std::isfinite(s.sigma_x) || !std::isfinite(s.sigma_z) || !std::isfinite(s.tau_xz)) {
    throw InvalidInput(std::string(where) + ": the point (x, z) = (" + format_value(at.x) + ", " +
                       format_value(at.z) +
                       ") is so close to the load point that the stress overflows");
  }
  return s;
}

PlaneStress flamant_stress(const FlamantLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "flamant_stress";
  require_positive(kWhere, "load per unit length P", load.P);
  return radial_line_load_stress(kWhere, load.P, LineLoadDirection::normal, at);
}

}  // namespace cs::oracles

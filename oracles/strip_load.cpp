#include "oracles/strip_load.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"
#include "oracles/length_scale.hpp"

namespace cs::oracles {

PlaneStress strip_load_stress(const StripLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "strip_load_stress";
  require_positive(kWhere, "strip half-width a", load.a);
  require_positive(kWhere, "pressure p", load.p);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);
  if (at.z == 0.0 && std::abs(at.x) == load.a) {
    throw InvalidInput(std::string(kWhere) + ": the point (x, z) = (" + format_value(at.x) +
                       ", 0) is an edge of the loaded strip, where the stress is discontinuous");
  }
  // Angles from the surface, in [0, pi]. The printed differences are evaluated through
  // alpha = theta1 - theta2 (the angle the strip subtends, taken directly so that it does not
  // cancel far away) and beta = theta1 + theta2:
  //   sin 2theta1 - sin 2theta2 = 2 cos(beta) sin(alpha),
  //   cos 2theta1 - cos 2theta2 = -2 sin(beta) sin(alpha).
  // The angles depend on lengths in units of L ~ max(a, |x|, z) only: no product overflows.
  const LengthScale L = length_scale({load.a, at.x, at.z});
  const double a = L.of(load.a);
  const double x = L.of(at.x);
  const double z = L.of(at.z) + 0.0;  // -0 becomes +0, so atan2 picks pi, not -pi, behind an edge
  const double alpha = std::atan2(2.0 * a * z, (x - a) * (x + a) + z * z);
  const double beta = std::atan2(z, x - a) + std::atan2(z, x + a);
  const double c = load.p / (2.0 * std::numbers::pi);
  const double sin_diff = 2.0 * std::cos(beta) * std::sin(alpha);
  const double cos_diff = -2.0 * std::sin(beta) * std::sin(alpha);
  return {
      .sigma_x = -c * (2.0 * alpha + sin_diff),
      .sigma_z = -c * (2.0 * alpha - sin_diff),
      .tau_xz = c * cos_diff,
  };
}

}  // namespace cs::oracles

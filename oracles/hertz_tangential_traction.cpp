#include "oracles/hertz_tangential_traction.hpp"

#include <cmath>

#include "oracles/invalid_input.hpp"
#include "oracles/mcewen_roots.hpp"

namespace cs::oracles {

PlaneStress hertz_tangential_traction_stress(const HertzTangentialTraction& load, PlanePoint at) {
  constexpr const char* kWhere = "hertz_tangential_traction_stress";
  require_positive(kWhere, "half-width a", load.a);
  require_finite(kWhere, "peak traction q0", load.q0);
  if (load.q0 == 0.0)
    throw InvalidInput(std::string(kWhere) + ": peak traction q0 must be non-zero (got 0)");
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);

  const McEwenRoots r = mcewen_roots(load.a, at);
  // In units of L: k (x - n) = q0 a (x - n)/a^2, and k d = q0 a d/a^2 (mcewen.cpp).
  const double trace = -2.0 * load.q0 * (r.a * r.x_minus_n_over_a2);  // sigma_x + sigma_z
  PlaneStress s{.sigma_x = trace, .sigma_z = 0.0, .tau_xz = 0.0};
  if (!r.on_surface_edge_or_outside) {
    const double c = load.q0 * (r.a * r.d_over_a2);
    const double d = r.a * r.a * r.d_over_a2;
    s.sigma_z = -c * (r.n / r.S);                                                  // McEwen's tau
    s.tau_xz = -c * ((r.m * d / (r.m + r.z) + 2.0 * r.n2) / ((r.m + r.z) * r.S));  // McEwen's sx
    s.sigma_x = trace - s.sigma_z;
  }
  if (!std::isfinite(s.sigma_x) || !std::isfinite(s.sigma_z) || !std::isfinite(s.tau_xz)) {
    throw InvalidInput(std::string(kWhere) + ": peak traction q0 = " + format_value(load.q0) +
                       " puts the stress out of floating-point range");
  }
  return s;
}

}  // namespace cs::oracles

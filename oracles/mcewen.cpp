#include "oracles/mcewen.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"
#include "oracles/mcewen_roots.hpp"

namespace cs::oracles {

PlaneStress mcewen_stress(const McEwenLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "mcewen_stress";
  require_positive(kWhere, "contact half-width a", load.a);
  require_positive(kWhere, "mean pressure p", load.p);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);

  const McEwenRoots r = mcewen_roots(load.a, at);
  if (r.on_surface_edge_or_outside)
    return {0.0, 0.0, 0.0};  // the edge of contact, or the free surface outside it
  const double a = r.a;
  const double z = r.z;
  const double m = r.m;
  const double n = r.n;
  const double S = r.S;

  // With (z^2 + n^2) / (m^2 + n^2) = 1 - d / S and m - z = d / (m + z), d = m^2 - z^2, the
  // printed forms read sigma_z = -k m d / S, sigma_x = -k d (2 / (m + z) - m / S),
  // tau_xz = -k n d / S, k = 4p / (pi a); in units of L, k d = (4p/pi) a d_over_a2. The
  // difference in sigma_x is 2 / (m + z) - m / S = (m d / (m + z) + 2 n^2) / ((m + z) S), a sum
  // of terms >= 0 (it cancels to O(a^2) far away when taken as printed).
  const double c = 4.0 / std::numbers::pi * load.p * (a * r.d_over_a2);
  const double d = a * a * r.d_over_a2;
  const PlaneStress s{
      .sigma_x = -c * ((m * d / (m + z) + 2.0 * r.n2) / ((m + z) * S)),
      .sigma_z = -c * (m / S),
      .tau_xz = -c * (n / S),
  };
  if (!std::isfinite(s.sigma_x) || !std::isfinite(s.sigma_z) || !std::isfinite(s.tau_xz)) {
    throw InvalidInput(std::string(kWhere) + ": mean pressure p = " + format_value(load.p) +
                       " puts the stress out of floating-point range");
  }
  return s;
}

}  // namespace cs::oracles

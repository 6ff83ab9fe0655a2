#include "oracles/mcewen.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"
#include "oracles/length_scale.hpp"

namespace cs::oracles {

PlaneStress mcewen_stress(const McEwenLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "mcewen_stress";
  require_positive(kWhere, "contact half-width a", load.a);
  require_positive(kWhere, "mean pressure p", load.p);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);

  // Lengths in units of L ~ max(a, |x|, z): every squared length below is at most 12.
  const LengthScale L = length_scale({load.a, at.x, at.z});
  const double a = L.of(load.a);
  const double x = L.of(at.x);
  const double z = L.of(at.z);
  // m^2 + n^2 = S and m^2 n^2 = x^2 z^2: take the root without cancellation from the
  // sign of A, the other from the product.
  const double A = (a - x) * (a + x) + z * z;
  const double S = std::hypot(A, 2.0 * x * z);
  if (S == 0.0)
    return {0.0, 0.0, 0.0};  // x = +-a on the surface: the edge of contact
  const double xz2 = (x * z) * (x * z);
  const double S_plus_rho2 = S + x * x + z * z;
  double m2 = 0.0;
  double n2 = 0.0;
  double d_over_a2 = 0.0;  // (m^2 - z^2) / a^2, the factor common to all three components
  if (A >= 0.0) {
    m2 = 0.5 * (S + A);
    n2 = xz2 / m2;
    d_over_a2 = (m2 + z * z) / S_plus_rho2;
  } else {
    n2 = 0.5 * (S - A);
    m2 = xz2 / n2;
    d_over_a2 = z * z * ((n2 + x * x) / (n2 * S_plus_rho2));
  }
  const double m = std::sqrt(m2);
  const double n = std::copysign(std::sqrt(n2), x);
  if (m + z == 0.0)
    return {0.0, 0.0, 0.0};  // on the surface outside the contact

  // With (z^2 + n^2) / (m^2 + n^2) = 1 - d / S and m - z = d / (m + z), d = m^2 - z^2, the
  // printed forms read sigma_z = -k m d / S, sigma_x = -k d (2 / (m + z) - m / S),
  // tau_xz = -k n d / S, k = 4p / (pi a); in units of L, k d = (4p/pi) a d_over_a2. The
  // difference in sigma_x is 2 / (m + z) - m / S = (m d / (m + z) + 2 n^2) / ((m + z) S), a sum
  // of terms >= 0 (it cancels to O(a^2) far away when taken as printed).
  const double c = 4.0 / std::numbers::pi * load.p * (a * d_over_a2);
  const double d = a * a * d_over_a2;
  const PlaneStress s{
      .sigma_x = -c * ((m * d / (m + z) + 2.0 * n2) / ((m + z) * S)),
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

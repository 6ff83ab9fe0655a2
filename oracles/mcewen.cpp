#include "oracles/mcewen.hpp"

#include <cmath>
#include <numbers>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {

PlaneStress mcewen_stress(const McEwenLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "mcewen_stress";
  require_positive(kWhere, "contact half-width a", load.a);
  require_positive(kWhere, "mean pressure p", load.p);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);

  const double x = at.x;
  const double z = at.z;
  const double a = load.a;
  // m^2 + n^2 = S and m^2 n^2 = x^2 z^2: take the root without cancellation from the
  // sign of A, the other from the product.
  const double A = (a - x) * (a + x) + z * z;
  const double S = std::hypot(A, 2.0 * x * z);
  if (S == 0.0)
    return {0.0, 0.0, 0.0};  // x = +-a on the surface: the edge of contact
  const double xz2 = (x * z) * (x * z);
  double m2 = 0.0;
  double n2 = 0.0;
  double d = 0.0;  // m^2 - z^2, the factor common to all three components
  if (A >= 0.0) {
    m2 = 0.5 * (S + A);
    n2 = xz2 / m2;
    d = m2 - z * z;
  } else {
    n2 = 0.5 * (S - A);
    m2 = xz2 / n2;
    // m^2 - z^2 = z^2 (x^2 - n^2) / n^2 with x^2 - n^2 = (x^2 + z^2 + a^2 - S) / 2 > 0.
    d = z * z * (0.5 * (x * x + z * z + a * a - S)) / n2;
  }
  const double m = std::sqrt(m2);
  const double n = std::copysign(std::sqrt(n2), x);
  if (m + z == 0.0)
    return {0.0, 0.0, 0.0};  // on the surface outside the contact

  // With (z^2 + n^2) / (m^2 + n^2) = 1 - d / S and m - z = d / (m + z), the printed forms read
  // sigma_z = -k m d / S, sigma_x = -k d (2 / (m + z) - m / S), tau_xz = -k n d / S.
  const double k = 4.0 * load.p / (std::numbers::pi * a);
  return {
      .sigma_x = -k * d * (2.0 / (m + z) - m / S),
      .sigma_z = -k * m * d / S,
      .tau_xz = -k * n * d / S,
  };
}

}  // namespace cs::oracles

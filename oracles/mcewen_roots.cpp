#include "oracles/mcewen_roots.hpp"

#include <cmath>

#include "oracles/length_scale.hpp"

namespace cs::oracles {

McEwenRoots mcewen_roots(double a_length, PlanePoint at) {
  McEwenRoots r;
  const LengthScale L = length_scale({a_length, at.x, at.z});
  r.a = L.of(a_length);
  r.x = L.of(at.x);
  r.z = L.of(at.z);
  const double a = r.a;
  const double x = r.x;
  const double z = r.z;
  // m^2 + n^2 = S and m^2 n^2 = x^2 z^2: take the root without cancellation from the sign of
  // A, the other from the product.
  const double A = (a - x) * (a + x) + z * z;
  r.S = std::hypot(A, 2.0 * x * z);
  if (r.S == 0.0) {  // x = +-a on the surface: the edge of the strip, m = n = 0
    r.on_surface_edge_or_outside = true;
    r.x_minus_n_over_a2 = x / (a * a);
    return r;
  }
  const double xz2 = (x * z) * (x * z);
  const double S_plus_rho2 = r.S + x * x + z * z;
  double m2 = 0.0;
  if (A >= 0.0) {
    m2 = 0.5 * (r.S + A);
    r.n2 = xz2 / m2;
    r.d_over_a2 = (m2 + z * z) / S_plus_rho2;
  } else {
    r.n2 = 0.5 * (r.S - A);
    m2 = xz2 / r.n2;
    r.d_over_a2 = z * z * ((r.n2 + x * x) / (r.n2 * S_plus_rho2));
  }
  r.m = std::sqrt(m2);
  r.n = std::copysign(std::sqrt(r.n2), x);
  r.on_surface_edge_or_outside = r.m + z == 0.0;
  if (x != 0.0)  // x and n share their sign: x + n does not cancel
    r.x_minus_n_over_a2 = (r.n2 + x * x) / (S_plus_rho2 * (x + r.n));
  return r;
}

}  // namespace cs::oracles

#pragma once
// McEwen's roots m, n of a point below a semi-elliptic surface traction of half-width a, shared
// by the normal field (McEwen, mcewen.hpp) and its tangential counterpart
// (hertz_tangential_traction.hpp): (m - i n)^2 = a^2 - (x + i z)^2, m >= 0, n of the sign of x,
// i.e. m^2 - n^2 = A = a^2 - x^2 + z^2, m n = x z, m^2 + n^2 = S = (A^2 + 4 x^2 z^2)^(1/2).
// Also (x + i z)^2 - a^2 = (n + i m)^2, so Re((x + iz)^2 - a^2)^(1/2) = n.
//
// Everything is in units of a power of two L ~ max(a, |x|, z) (length_scale.hpp), and the
// differences that cancel to O(a^2) far from the load are returned in closed form:
//   m^2 - z^2 = a^2 (m^2 + z^2) / (S + rho^2)              (A >= 0),
//             = a^2 z^2 (n^2 + x^2) / (n^2 (S + rho^2))    (A < 0),
//   x - n     = a^2 (n^2 + x^2) / ((S + rho^2) (x + n)),   rho^2 = x^2 + z^2.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// The roots at one point, every length in the unit L.
struct McEwenRoots {
  /// The point is an edge of the loaded strip (x = +-a, z = 0) or on the surface outside it
  /// (m + z = 0): the fields below take their continuous limits there, set by the callers.
  bool on_surface_edge_or_outside = false;
  double a = 0.0;  ///< a / L
  double x = 0.0;  ///< x / L
  double z = 0.0;  ///< z / L
  double m = 0.0;
  double n = 0.0;
  double n2 = 0.0;
  double S = 0.0;                  ///< m^2 + n^2
  double d_over_a2 = 0.0;          ///< (m^2 - z^2) / a^2
  double x_minus_n_over_a2 = 0.0;  ///< (x - n) / a^2
};

/// The roots at `at` for half-width a > 0 (validated by the caller).
McEwenRoots mcewen_roots(double a, PlanePoint at);

}  // namespace cs::oracles

#pragma once
// McEwen's closed-form interior stress field of plane-strain Hertz contact: the field under the
// elliptical pressure (4p/pi) sqrt(1 - (x/a)^2) on |x| < a of the surface z = 0.
//
// Reference: E. McEwen (1949), Phil. Mag. 40, 454-459; K.L. Johnson, Contact Mechanics (1985),
// pp. 102-104, as cited by the study.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// The Hertzian pressure of half-width a and mean pressure p = P / (2a) (peak 4p/pi).
struct McEwenLoad {
  double a;  ///< contact half-width [length], > 0
  double p;  ///< mean contact pressure P / (2a) [stress], > 0 (the study's p)
};

/// Study Eqs. 11-12 (McEwen): with k = 4p / (pi a),
///   sigma_z = -k m (1 - (z^2 + n^2) / (m^2 + n^2)),
///   sigma_x = -k (m (1 + (z^2 + n^2) / (m^2 + n^2)) - 2z),
///   tau_xz  = -k n (m^2 - z^2) / (m^2 + n^2),
/// where m^2, n^2 = ((A^2 + 4 x^2 z^2)^(1/2) +- A) / 2, A = a^2 - x^2 + z^2, m >= 0 and n takes
/// the sign of x. On z = 0 this reduces to Eq. 15 under the contact and to a traction-free
/// surface outside; at the contact edges (x = +-a, z = 0) the stress is 0 (the continuous limit).
///
/// Evaluation: lengths in units of L = max(a, |x|, z), and m^2 - z^2 (which cancels to O(a^2)
/// far from the contact when taken as printed) in the closed form
///   m^2 - z^2 = a^2 (m^2 + z^2) / (S + rho^2)              (A >= 0),
///   m^2 - z^2 = a^2 z^2 (n^2 + x^2) / (n^2 (S + rho^2))    (A < 0),
/// with S = m^2 + n^2 and rho^2 = x^2 + z^2, so that the stress is (4p/pi) (a/L) times O(1)
/// factors: full relative precision at every distance, no over- or underflow of a^2 or x^2.
/// Domain: every finite point with z >= 0; far points whose stress (~ p a / rho) is below the
/// smallest double answer 0 or a subnormal number. Throws InvalidInput for a, p not positive,
/// a point with z < 0 or non-finite x, or a p so large that the stress overflows.
PlaneStress mcewen_stress(const McEwenLoad& load, PlanePoint at);

}  // namespace cs::oracles

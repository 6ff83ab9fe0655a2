#pragma once
// The interior stress field of a semi-elliptic TANGENTIAL surface traction on an elastic
// half-space, plane strain: q(x) = q0 (1 - x^2/a^2)^(1/2) on |x| < a, acting on the body in +x.
// It is the tangential counterpart of McEwen's field (mcewen.hpp): the full-sliding traction
// mu p(x) of Hertz contact, and (by superposition of two of them, q0 a and -q0 c over the stick
// zone) the Cattaneo-Mindlin traction (cattaneo_mindlin.hpp). A finite block cut from the
// half-space carries these stresses as the exact tractions of its far boundary.
//
// References: K.L. Johnson, Contact Mechanics (1985), Sec. 7.1 (the stresses of the sliding
// Hertzian traction, after G.M. Hamilton and L.E. Goodman (1966) and J.O. Smith and C.K. Liu
// (1953), J. Appl. Mech. 20, 157-166); derived here from McEwen's field (below).

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// The semi-elliptic tangential traction q0 (1 - x^2/a^2)^(1/2), |x| < a, resultant
/// Q = pi a q0 / 2 per unit length, acting on the body in +x (q0 < 0: in -x).
struct HertzTangentialTraction {
  double a;   ///< half-width of the loaded strip [length], > 0
  double q0;  ///< peak traction, at x = 0 [stress], finite and non-zero
};

/// With McEwen's roots m, n of (x, z) (mcewen_roots.hpp) and k = q0 / a:
///   sigma_z = -k n (m^2 - z^2) / (m^2 + n^2),
///   tau_xz  = -k (m (1 + (z^2 + n^2) / (m^2 + n^2)) - 2z),
///   sigma_x = -2k (x - n) + k n (m^2 - z^2) / (m^2 + n^2).
/// Derivation: the tangential Flamant kernel (flamant_tangential.hpp) has the normal kernel's
/// tau_xz as its sigma_z and the normal kernel's sigma_x as its tau_xz, so for the same
/// distribution sigma_z = McEwen's tau_xz and tau_xz = McEwen's sigma_x (with 4p/pi -> q0);
/// its trace is sigma_x + sigma_z = -(2/pi) int q(s) (x - s) / ((x - s)^2 + z^2) ds =
/// -(2k) Re(zeta - (zeta^2 - a^2)^(1/2)) = -2k (x - n), zeta = x + i z.
/// On the surface z = 0: tau_xz = -q(x) (the traction on the body is t_x = -tau_xz = +q),
/// sigma_z = 0, and sigma_x = -2 q0 x / a under the load (compression ahead, tension behind),
/// -2 (q0/a) (x - sign(x) (x^2 - a^2)^(1/2)) outside it. Far away: the tangential Flamant
/// field of Q = pi a q0 / 2, to O((a / r)^2). Evaluated scale-free like McEwen's.
/// Throws InvalidInput for a not positive, q0 zero or non-finite, z < 0, non-finite x, or a q0
/// so large that the stress overflows.
PlaneStress hertz_tangential_traction_stress(const HertzTangentialTraction& load, PlanePoint at);

}  // namespace cs::oracles

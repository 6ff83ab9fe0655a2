#pragma once
// Flamant's solution for a concentrated TANGENTIAL line load on an elastic half-space, plane
// strain: a force Q per unit length along the surface, in +x, at x = 0 of the surface z = 0.
// The field is purely radial, sigma_rr = -(2Q / pi) sin(theta) / r with theta measured from
// the depth direction z towards +x (sin(theta) = x / r): compression ahead of the force,
// tension behind it. Superposed over a surface shear traction it gives the interior field of
// any tangential loading (hertz_tangential_traction.hpp is proved that way).
//
// Reference: A. Flamant (1892), C. R. Acad. Sci. Paris 114, 1465-1468; K.L. Johnson, Contact
// Mechanics (1985), Sec. 2.2, Eqs. (2.19)-(2.21) (concentrated tangential force).

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// A tangential line force Q per unit length at x = 0 of the surface, acting on the body in +x
/// (Q < 0 acts in -x: the field is linear in Q).
struct FlamantTangentialLoad {
  double Q;  ///< tangential force per unit length [force / length], finite and non-zero
};

/// The tangential Flamant field, r^2 = x^2 + z^2 (Johnson Eq. 2.21):
///   sigma_x = -(2Q / pi) x^3 / r^4,  sigma_z = -(2Q / pi) x z^2 / r^4,
///   tau_xz  = -(2Q / pi) x^2 z / r^4.
/// Sign convention (docs/conventions.md, z into the body): the surface traction the load
/// applies to the body is t_x = -tau_xz(x, 0); the shear carried across a plane z = h > 0 is
/// the integral of tau_xz dx = -Q. Evaluated in units of max(|x|, z): far points answer
/// (2Q / pi) / r times O(1) factors, 0 once below the smallest double.
/// Throws InvalidInput for Q zero or non-finite, z < 0, non-finite x, the load point (0, 0), or
/// a point so close to it that the stress overflows.
PlaneStress flamant_tangential_stress(const FlamantTangentialLoad& load, PlanePoint at);

}  // namespace cs::oracles

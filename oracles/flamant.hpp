#pragma once
// Flamant's solution for a concentrated normal line load on an elastic half-space, plane
// strain: the purely radial stress field -(2P / pi) cos(theta) / r. Superposed over a surface
// pressure it gives every plane-strain field of the study (McEwen, the strip load), which is
// how the tests prove those.
//
// Reference: A. Flamant (1892), C. R. Acad. Sci. Paris 114, 1465-1468; K.L. Johnson, Contact
// Mechanics (1985), Ch. 2 (concentrated normal force).

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// A compressive line force P per unit length along the y axis, at x = 0 of the surface z = 0.
struct FlamantLoad {
  double P;  ///< normal force per unit length [force / length], > 0, pushing into the body
};

/// Flamant's field, with r^2 = x^2 + z^2:
///   sigma_x = -(2P / pi) x^2 z / r^4,  sigma_z = -(2P / pi) z^3 / r^4,
///   tau_xz  = -(2P / pi) x z^2 / r^4.
/// The surface z = 0 is traction free away from the load. Evaluated in units of
/// max(|x|, z): far points answer (2P / pi) / r times O(1) factors, 0 once below the
/// smallest double. Throws InvalidInput for P not positive, z < 0, non-finite x, the load
/// point (0, 0), or a point so close to it that the stress overflows.
PlaneStress flamant_stress(const FlamantLoad& load, PlanePoint at);

/// The direction of a line load on the surface: into the body (e_z) or along it (e_x).
enum class LineLoadDirection { normal, tangential };

/// The radial field of a line load F per unit length along `direction` at the origin:
///   sigma_rr = -(2F / pi) (d . e_r) / r,  d = e_z (normal) or e_x (tangential),
/// in Cartesian components sigma_ij = sigma_rr (e_r)_i (e_r)_j; flamant_stress and
/// flamant_tangential_stress are its two cases. Checks the point as they do (`where` names the
/// caller) and that F is finite; the load's own conditions (P > 0, Q != 0) are the caller's.
PlaneStress radial_line_load_stress(const char* where, double F, LineLoadDirection direction,
                                    PlanePoint at);

}  // namespace cs::oracles

#pragma once
// A uniform pressure on a strip of the surface of an elastic half-space, plane strain. The
// study uses it as the far-field traction of the plane flat-punch problem (Eqs. 35-36).
//
// Reference: K.L. Johnson, Contact Mechanics (1985), p. 21, as cited by the study.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// Uniform pressure p > 0 on |x| < a of the surface z = 0.
struct StripLoad {
  double a;  ///< half-width of the loaded strip [length], > 0
  double p;  ///< uniform pressure [stress], > 0
};

/// Study Eqs. 35-36 (Johnson p. 21):
///   sigma_z = -(p / 2pi) (2 (theta1 - theta2) - (sin 2theta1 - sin 2theta2)),
///   sigma_x = -(p / 2pi) (2 (theta1 - theta2) + (sin 2theta1 - sin 2theta2)),
///   tau_xz  =  (p / 2pi) (cos 2theta1 - cos 2theta2),
/// with the angles measured from the surface, tan(theta_i) = z / (x + (-1)^i a), in [0, pi]
/// (theta1 seen from the edge x = +a, theta2 from x = -a). Compression negative. On z = 0:
/// sigma_x = sigma_z = -p under the load and 0 outside.
/// The angles are taken in units of max(a, |x|, z), so every finite point has its value
/// (far points: ~ p a / r, 0 once below the smallest double).
/// Throws InvalidInput for a, p not positive, z < 0, non-finite x, or an edge of the strip on
/// the surface (|x| = a, z = 0), where the stress jumps and has no value.
PlaneStress strip_load_stress(const StripLoad& load, PlanePoint at);

}  // namespace cs::oracles

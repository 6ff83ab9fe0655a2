#pragma once
// Hertz contact of a rigid cylinder on an elastic half-space, plane strain (the study's
// Problem H_p): contact half-width from the load, and the elliptical surface pressure.
//
// References: H. Hertz (1882), J. reine angew. Math. 92, 156-171; K.L. Johnson, Contact
// Mechanics (1985), p. 101 (pressure) and p. 427 (half-width), as cited by the study.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// A rigid cylinder of radius R pressed into an elastic half-space by a load P per unit length.
struct HertzCylinder {
  double R;   ///< cylinder radius [length], > 0
  double E;   ///< Young's modulus of the half-space [stress], > 0
  double nu;  ///< Poisson's ratio of the half-space, in [0, 0.5)
  double P;   ///< normal load per unit length [force / length], > 0
};

/// The Hertzian contact strip |x| < a.
struct HertzPlaneContact {
  double contact_half_width_a;  ///< a [length]
  double p_mean;                ///< the study's p = P / (2a): mean contact pressure
  double p_max;                 ///< Hertz's p0 = 4p / pi = 2P / (pi a): peak pressure, at x = 0
};

/// Study Eq. 16 with p = P/(2a): a = 8 R (1 - nu^2) p / (pi E), i.e.
/// a^2 = 4 R (1 - nu^2) P / (pi E) (Hertz; Johnson p. 427).
/// Throws InvalidInput for a non-positive R, E or P, or nu outside [0, 0.5).
HertzPlaneContact hertz_plane_contact(const HertzCylinder& cylinder);

/// Study Eq. 15: the contact pressure -sigma_z(x, 0) = (4p/pi) sqrt(1 - (x/a)^2) for |x| <= a,
/// and 0 outside the contact (Hertz; Johnson p. 101). On z = 0 also sigma_x = sigma_z.
/// Throws InvalidInput for a non-finite x or a contact with non-positive a or p_max.
double hertz_plane_pressure(const HertzPlaneContact& contact, double x);

}  // namespace cs::oracles

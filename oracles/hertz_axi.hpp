#pragma once
// Hertz contact of a rigid sphere on an elastic half-space (the study's Problem H_a): contact
// radius from the load, and the hemispherical surface pressure.
//
// References: H. Hertz (1882), J. reine angew. Math. 92, 156-171; K.L. Johnson, Contact
// Mechanics (1985), pp. 92-93 (pressure) and p. 427 (radius), as cited by the study.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// A rigid sphere of radius R pressed into an elastic half-space by a total force P.
struct HertzSphere {
  double R;   ///< sphere radius [length], > 0
  double E;   ///< Young's modulus of the half-space [stress], > 0
  double nu;  ///< Poisson's ratio of the half-space, in [0, 0.5)
  double P;   ///< total normal load [force], > 0
};

/// The Hertzian contact disc r < a.
struct HertzAxiContact {
  double contact_radius_a;  ///< a [length]
  double p_mean;            ///< the study's p = P / (pi a^2): mean contact pressure
  double p_max;             ///< p0 = 3p / 2: peak pressure, at r = 0
};

/// Study Eq. 23 with p = P/(pi a^2): a = 3 pi R (1 - nu^2) p / (4E), i.e.
/// a^3 = 3 R (1 - nu^2) P / (4E) (Hertz; Johnson p. 427).
/// Throws InvalidInput for a non-positive R, E or P, or nu outside [0, 0.5).
HertzAxiContact hertz_axi_contact(const HertzSphere& sphere);

/// Study Eq. 22: the contact pressure -sigma_z(r, 0) = (3p/2) sqrt(1 - (r/a)^2) for r <= a,
/// 0 outside the contact (Hertz; Johnson pp. 92-93). Throws InvalidInput for r < 0.
double hertz_axi_pressure(const HertzAxiContact& contact, double r);

}  // namespace cs::oracles

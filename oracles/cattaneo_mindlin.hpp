#pragma once
// Cattaneo-Mindlin partial slip of two elastically similar bodies in plane strain: a cylinder
// (or two) pressed by a load P per unit length, then pulled by a tangential load Q < mu P.
// Similar materials (Dundurs beta = 0) uncouple the normal and tangential problems: the
// pressure is Hertz's, the contact does not grow with Q, and the shear traction is the
// difference of two semi-elliptic tractions,
//   q(x) = mu p0 (1 - x^2/a^2)^(1/2) - mu p0 (c/a) (1 - x^2/c^2)^(1/2)  in the stick zone |x| < c,
//   q(x) = mu p0 (1 - x^2/a^2)^(1/2)                                    in the slip zones c < |x| <
//   a,
// with the stick half-width c = a (1 - Q/(mu P))^(1/2). The interior field is the sum of
// McEwen's (mcewen.hpp) and two tangential fields (hertz_tangential_traction.hpp: q0 = mu p0
// on a, and q0 = -mu p0 c/a on c).
//
// References: C. Cattaneo (1938), Rend. Accad. Naz. Lincei 27, 342-348, 434-436, 474-478;
// R.D. Mindlin (1949), J. Appl. Mech. 16, 259-268; K.L. Johnson, Contact Mechanics (1985),
// Sec. 4.2 (Hertz, two cylinders) and Sec. 7.1 (tangential loading, Eqs. 7.11-7.12).
//
// Sign convention (docs/conventions.md, z into the lower body): Q > 0 pulls the upper body in
// +x; the traction it exerts on the lower body's surface is q(x) >= 0 in +x, so that body's
// tau_xz(x, 0) = -q(x). The upper body carries the opposite traction.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// Two bodies of the same E and nu in line contact, normal load first, then tangential.
struct CattaneoMindlinPlane {
  double R;   ///< relative radius of curvature, 1/R = 1/R1 + 1/R2 (R2 = inf: a flat) [length], > 0
  double E;   ///< Young's modulus of both bodies [stress], > 0
  double nu;  ///< Poisson's ratio of both bodies, in [0, 0.5)
  double P;   ///< normal load per unit length [force / length], > 0
  double Q;   ///< tangential load per unit length, applied after P, 0 <= Q < mu P
  double mu;  ///< Coulomb friction coefficient, in [0, 10]
};

/// The solved contact and the quantities the suite grades.
struct CattaneoMindlinContact {
  double contact_half_width_a;  ///< a = (4 P R / (pi E*))^(1/2), E* = E / (2 (1 - nu^2))
  double p0;                    ///< peak pressure 2P / (pi a), at x = 0
  double p_mean;                ///< P / (2a): the p of H_p, the normalizing pressure
  double stick_half_width_c;    ///< c = a (1 - Q/(mu P))^(1/2)
  double c_over_a;              ///< c / a, graded
  double Q_over_mu_P;           ///< Q / (mu P) = 1 - (c/a)^2, in [0, 1)
  double q_peak;                ///< peak shear traction, at |x| = c: mu p0 (Q/(mu P))^(1/2)
  double q_peak_over_p0;        ///< q_peak / p0 = (mu Q / P)^(1/2)
  double q_peak_over_p_mean;    ///< q_peak / p_mean = (4/pi) (mu Q / P)^(1/2), graded
  double mu;                    ///< the friction coefficient (to evaluate q(x))
};

/// Johnson Eq. 4.43-4.45 (a, p0; plane-strain contact modulus of two similar bodies
/// 1/E* = 2 (1 - nu^2)/E) and Sec. 7.1 (c, q). Throws InvalidInput for R, E, P not positive,
/// nu outside [0, 0.5), mu outside [0, 10] or not finite, Q < 0 or not finite, and for
/// Q >= mu P: "Q >= mu P: the stick oracle needs Q < mu P" (full sliding: use mu p(x)).
CattaneoMindlinContact cattaneo_mindlin_contact(const CattaneoMindlinPlane& problem);

/// Hertz's pressure p0 (1 - x^2/a^2)^(1/2), 0 outside the contact. Throws for non-finite x.
double cattaneo_mindlin_pressure(const CattaneoMindlinContact& contact, double x);

/// The shear traction q(x) on the lower body, >= 0 (in +x), 0 outside the contact; |q| <= mu p
/// everywhere, = mu p in the slip zones. In the stick zone it is evaluated as
/// mu p0 (Q/(mu P)) / ((1 - x^2/a^2)^(1/2) + (c/a) (1 - x^2/c^2)^(1/2)) (the numerator is
/// 1 - x^2/a^2 - (c/a)^2 (1 - x^2/c^2) = 1 - c^2/a^2), without the cancellation of the printed
/// difference as Q -> 0. Throws InvalidInput for non-finite x.
double cattaneo_mindlin_shear(const CattaneoMindlinContact& contact, double x);

}  // namespace cs::oracles

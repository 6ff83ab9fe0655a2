#pragma once
// Steuermann's solution for a rigid flat punch with rounded edges on an elastic half-space,
// plane strain (the study's Problem S): the punch has a flat face of half-width b and edge
// radii r_e; under a load P per unit length it touches the half-space over |x| < a, b < a.
//
// Reference: I.Y. Steuermann (1949), Contact problem of the theory of elasticity, Moscow-
// Leningrad, as reported by M. Ciavarella, D.A. Hills and G. Monno (1998), Proc. IMechE 212C,
// 319-327 (the study's Reference 7).
//
// What p is: the study does not say. Its printed exact values 9.9773 (r_e/b = 1) and 13.1753
// (r_e/b = 1/7) follow from p = P / (2(b + r_e)), the pressure on the punch's top face, with
// Eq. 32 evaluated WITHOUT the factor (1 - nu^2); with it (plane strain, physically consistent,
// the default here) the peaks are 10.1956, 11.2424, 13.4622 at nu = 1/4, p/E = 1e-3. Both are
// available through Eq32Factor; see docs/conventions.md.
//
// Numerics: everything is computed from the dimensionless groups r_e/b and
// lambda = 2 r_e (1 - nu^2) P / (b^2 E) = 2 (1 - nu^2) (r_e/b) (P/b) / E, the pressure as
// (P/b) times a function of x/a. Eq. 32 is solved with GSL's Brent root finder in
// u = pi/2 - phi0 for light loads (u <= pi/4, lambda ~ 2u^3/3) and in phi0 for heavy ones
// (lambda ~ pi / (2 phi0^2), the Hertz limit r_e >> b), so that the smaller angle keeps its
// relative precision; SteuermannContact carries both. Eq. 31's bracket, O(u^2) on the rounded
// edges and O(u^3) on the flat face while its printed terms are O(1) and O(u), is evaluated
// in a regrouped form without cancellation (steuermann.cpp; the identities are checked against
// the printed form in 250-digit arithmetic by tests/oracles/steuermann_reference.py): the
// pressure and the peak keep about 1e-15 relative accuracy from u = 1e-64 to phi0 = 1e-20.
//
// Domain (documented and enforced): b, r_e, P, E > 0 and finite, nu in [0, 0.5),
//   1e-100 <= r_e/b <= 1e100 (beyond: a sharp-cornered punch, Sadowsky; a cylinder, Hertz),
//   lambda >= 1e-300 and P/b a normal double (lighter: the limit is Sadowsky's punch),
//   lambda finite, P <= steuermann_max_load (contact within the rounded edges), a finite.
// Outside it the oracle throws InvalidInput naming the bound. When u < 1e-8 the rounded edges
// (width a - b ~ b u^2 / 2) are narrower than the spacing of doubles near b: a rounds to b,
// x_peak to b, and the pressure is resolved at x = b and on the flat face only; the peak value
// itself is computed at its angle and stays accurate.

#include <string_view>

namespace cs::oracles {

/// Whether Eq. 32 carries the plane-strain factor (1 - nu^2).
enum class Eq32Factor {
  kWithOneMinusNu2,     ///< plane strain, physically consistent (the default)
  kWithoutOneMinusNu2,  ///< as the study evaluated it: reproduces its printed 9.9773, 13.1753
};

/// "with (1 - nu^2)" or "without (1 - nu^2)".
std::string_view to_string(Eq32Factor factor);

/// A rounded flat punch pressed into an elastic half-space by a load P per unit length.
struct SteuermannPunch {
  double b;    ///< half-width of the flat face [length], > 0
  double r_e;  ///< edge radius [length], > 0
  double P;    ///< load per unit length [force / length], > 0
  double E;    ///< Young's modulus of the half-space [stress], > 0
  double nu;   ///< Poisson's ratio of the half-space, in [0, 0.5)
  Eq32Factor eq32_factor = Eq32Factor::kWithOneMinusNu2;
};

/// The solved contact: phi0 and the half-width a = b / sin(phi0).
struct SteuermannContact {
  double b;                     ///< half-width of the flat face [length]
  double P;                     ///< load per unit length [force / length]
  double phi0;                  ///< the root of Eq. 32, in (0, pi/2), to full relative precision
  double half_pi_minus_phi0;    ///< u = pi/2 - phi0, to full relative precision
  double contact_half_width_a;  ///< a = b / sin(phi0) [length], b < a <= b + r_e
};

/// The peak of the contact pressure, which lies on the rounded part b < x_peak < a.
struct SteuermannPeak {
  double peak_pressure;  ///< max of -sigma_z(x, 0) [stress], > 0
  double x_peak;         ///< where it is reached (and at -x_peak) [length]
  double phi_peak;       ///< the angle phi of Eq. 31 there: sin(phi) = x_peak / a
};

/// The left-hand side of Eq. 32, lambda = 2 r_e (1 - nu^2) P / (b^2 E) (or without the factor).
/// Throws InvalidInput for non-positive lengths, load, modulus, or nu outside [0, 0.5).
double steuermann_load_parameter(const SteuermannPunch& punch);

/// The largest load for which contact stays on the rounded edges, a = b + r_e (the punch's
/// own P is not used); +inf if it exceeds the largest double. Throws InvalidInput for
/// non-positive b, r_e, E, nu outside [0, 0.5), or r_e/b outside [1e-100, 1e100].
double steuermann_max_load(const SteuermannPunch& punch);

/// Study Eq. 32: phi0 from lambda = (pi - 2 phi0) / (2 sin^2 phi0) - cot(phi0), solved with
/// gsl_root_fsolver_brent; then a = b / sin(phi0). Throws InvalidInput for bad parameters,
/// for input outside the domain above (a load too light, r_e/b out of range), and for a load
/// that would spread contact past the rounded edges (a > b + r_e, i.e. P > steuermann_max_load).
SteuermannContact steuermann_contact(const SteuermannPunch& punch);

/// Study Eq. 31: the contact pressure -sigma_z(x, 0) for |x| <= a, with sin(phi) = x sin(phi0)/b:
///   (a/P) p = (2/pi) / (pi - 2 phi0 - sin 2phi0) ((pi - 2 phi0) cos(phi)
///             + ln(|sin(phi + phi0) / sin(phi - phi0)|^sin(phi)
///                  |tan((phi + phi0)/2) tan((phi - phi0)/2)|^sin(phi0))),
/// and 0 for |x| > a. The logarithms are regrouped so that the singular factors cancel
/// analytically: at x = +-b (phi = phi0) the pressure is finite, the bracket's log term being
/// 2 sin(phi0) ln(sin(phi0)). 0 for |x| >= a (but x = +-b, when a rounds to b). Throws
/// InvalidInput for a non-finite x or an inconsistent contact.
double steuermann_pressure(const SteuermannContact& contact, double x);

/// The peak of Eq. 31 and its location: the root in (phi0, pi/2) of the analytic derivative
/// dp/dphi ~ cos(phi) ln(sin(phi + phi0) / sin(phi - phi0)) - (pi - 2 phi0) sin(phi), found with
/// gsl_root_fsolver_brent to full precision (the pressure is increasing with an infinite slope
/// through x = b and vanishes at x = a).
SteuermannPeak steuermann_peak(const SteuermannContact& contact);

/// The study's loading: the pressure p on the punch's top face (width 2(b + r_e)) given as p/E.
struct SteuermannStudyCase {
  double b;         ///< half-width of the flat face [length], > 0
  double r_e;       ///< edge radius [length], > 0
  double E;         ///< Young's modulus [stress], > 0
  double nu;        ///< Poisson's ratio, in [0, 0.5); the study takes 1/4
  double p_over_E;  ///< p / E, > 0; the study takes 1/1000
  Eq32Factor eq32_factor = Eq32Factor::kWithOneMinusNu2;
};

/// The punch of a study case: P = 2 (b + r_e) p, p = (p/E) E.
SteuermannPunch steuermann_study_punch(const SteuermannStudyCase& study_case);

/// The study's normalizing pressure p = P / (2 (b + r_e)) of a punch (the study reports
/// -sigma_z max / p).
double steuermann_study_pressure(const SteuermannPunch& punch);

}  // namespace cs::oracles

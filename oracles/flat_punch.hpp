#pragma once
// Rigid flat-ended punches with sharp corners (the study's Problem F): the contact pressure of
// the plane punch (Sadowsky) and of the circular punch (Harding and Sneddon). Both are
// unbounded, as an inverse square root, at the edge |x| = a (r = a): the study's normalized
// edge stress -> infinity, and a correct finite-element answer diverges with mesh refinement.
//
// References: M.A. Sadowsky (1928), Z. angew. Math. Mech. 8, 107-121; J.W. Harding and
// I.N. Sneddon (1945), Proc. Camb. Phil. Soc. 41, 16-26; K.L. Johnson, Contact Mechanics
// (1985), p. 37 and pp. 59-60, as cited by the study.
//
// Domain: every a, P > 0 and finite, and every finite position, for which the pressure scale
// (P/a plane, P/a^2 circular) is a normal double: [2.2e-308, 1.8e308]. The pressure is
// evaluated as that scale times a function of x/a alone, so a = 1e300 or 1e-300 answers to
// full precision; outside the range the oracle refuses ("out of floating-point range")
// instead of returning 0 or infinity.

namespace cs::oracles {

/// A rigid flat strip punch of half-width a pressed by a load P per unit length (plane strain).
struct SadowskyPunch {
  double a;  ///< punch half-width [length], > 0
  double P;  ///< load per unit length [force / length], > 0
};

/// A rigid flat circular punch of radius a pressed by a total force P.
struct HardingSneddonPunch {
  double a;  ///< punch radius [length], > 0
  double P;  ///< total load [force], > 0
};

/// The study's p for the plane punch: the mean pressure P / (2a).
double sadowsky_mean_pressure(const SadowskyPunch& punch);

/// Study Eq. 39 (Sadowsky; Johnson p. 37): -sigma_z(x, 0) = 2 p a / (pi (a^2 - x^2)^(1/2))
/// = P / (pi (a^2 - x^2)^(1/2)) for |x| < a, 0 for |x| > a.
/// Throws InvalidInput for a, P not positive, non-finite x, or |x| = a (unbounded there).
double sadowsky_pressure(const SadowskyPunch& punch, double x);

/// The study's p for the circular punch: the mean pressure P / (pi a^2).
double harding_sneddon_mean_pressure(const HardingSneddonPunch& punch);

/// Study Eq. 45 (Harding and Sneddon; Johnson pp. 59-60):
/// -sigma_z(r, 0) = p a / (2 (a^2 - r^2)^(1/2)) = P / (2 pi a (a^2 - r^2)^(1/2)) for r < a,
/// 0 for r > a. Throws InvalidInput for a, P not positive, r < 0, or r = a (unbounded there).
double harding_sneddon_pressure(const HardingSneddonPunch& punch, double r);

}  // namespace cs::oracles

#pragma once
// Lame interference fits: a solid shaft shrunk into a thick ring (plane strain), and a solid
// sphere in a thick spherical shell, both elastic, with a radial interference delta (the shaft's
// radius minus the ring's bore, before assembly) that the contact at r = b must resolve. The
// exact contact pressure p is uniform along the interface; the suite grades its mean and its
// largest deviation along the arc.
//
// References: S.P. Timoshenko and J.N. Goodier, Theory of Elasticity (3rd ed., 1970), Sec. 28
// (thick cylinder, "shrink fit") and Sec. 137 (thick spherical shell); derived below.
//
// Plane strain, Lame (axial strain 0, no body force): u = A' r + B'/r gives
//   sigma_r = A - B/r^2,  sigma_theta = A + B/r^2,  sigma_z = 2 nu A,
//   u_r = ((1 + nu)/E) ((1 - 2nu) A r + B/r).
// The shaft is finite on its axis (B = 0): sigma_r = sigma_theta = -p, u_r = -(1 + nu1)(1 - 2nu1)
// p r / E1. The ring carries -p at r = b and nothing at r = c: with beta = b/c,
//   A = p beta^2 / (1 - beta^2),  B = p b^2 / (1 - beta^2).
// Compatibility u_ring(b) - u_shaft(b) = delta gives
//   p = (delta/b) / [ (1 + nu2)(1 + (1 - 2nu2) beta^2) / (E2 (1 - beta^2))
//                     + (1 + nu1)(1 - 2nu1) / E1 ],
// which for one material is p = (delta/b) E (1 - beta^2) / (2 (1 - nu^2)), Timoshenko's
// shrink fit with the plane-strain modulus E / (1 - nu^2).
//
// Sphere in a shell, u = A' R + B'/R^2:
//   sigma_r = A - 2B/R^3,  sigma_theta = sigma_phi = A + B/R^3,
//   u_r = (R/E) ((1 - 2nu) A + (1 + nu) B / R^3).
// Solid sphere: sigma_r = sigma_theta = -p, u_r = -(1 - 2nu1) p R / E1. Shell, beta = b/c:
//   A = p beta^3 / (1 - beta^3),  B = p b^3 / (2 (1 - beta^3)),
//   p = (delta/b) / [ ((1 - 2nu2) beta^3 + (1 + nu2)/2) / (E2 (1 - beta^3)) + (1 - 2nu1) / E1 ],
// for one material p = (2/3)(delta/b) E (1 - beta^3) / (1 - nu).
//
// c = +infinity is accepted: a shaft in an infinite plate (p = (delta/b) / ((1 + nu2)/E2 +
// (1 + nu1)(1 - 2nu1)/E1), sigma_theta = p b^2/r^2 in the plate) and a sphere in an infinite
// body (sigma_theta = p b^3 / (2R^3)). Everything is evaluated in the ratios r/b, b/c and
// (c - r)/(c - b), so sigma_r vanishes exactly at r = c and no length scale over- or underflows.
//
// Domain: b > 0, b < c <= inf, 0 < delta <= 1e-2 b (the small-strain limit of this linear
// oracle: the solution is linear in delta, and the radii of the assembled fit are taken as the
// undeformed ones), E > 0 and nu in [0, 0.5) for both bodies. Outside it: InvalidInput.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// An isotropic linear elastic material.
struct LameMaterial {
  double E;   ///< Young's modulus [stress], > 0
  double nu;  ///< Poisson's ratio, in [0, 0.5)
};

/// A solid inner body (shaft or sphere) of radius b in an outer body (ring or shell) b < r < c.
struct InterferenceFit {
  double b;      ///< interface radius [length], > 0
  double c;      ///< outer radius of the ring or shell [length], > b; +inf: infinite
  double delta;  ///< radial interference [length], 0 < delta <= 1e-2 b
  LameMaterial inner;
  LameMaterial outer;
};

/// Which of the two bodies a point belongs to (the hoop stress jumps across r = b).
enum class FitBody {
  kInner,  ///< the shaft or the solid sphere, 0 <= r <= b
  kOuter,  ///< the ring or the shell, b <= r <= c
};

/// Plane-strain state at radius r: polar stresses (compression negative) and displacement.
struct CylinderFitState {
  double sigma_r;
  double sigma_theta;
  double sigma_z;  ///< out of plane, nu (sigma_r + sigma_theta)
  double u_r;      ///< radial displacement [length], outward positive
};

/// Spherical state at radius R (sigma_theta = sigma_phi).
struct SphereFitState {
  double sigma_r;
  double sigma_theta;
  double u_r;
};

/// The contact pressure p > 0 of the shaft in the ring (plane strain), above.
double interference_fit_cylinder_pressure(const InterferenceFit& fit);

/// The plane-strain Lame state at radius r of `body` (r in [0, b] or [b, c]).
/// Throws InvalidInput for a bad fit (domain above) or r outside the body.
CylinderFitState interference_fit_cylinder_state(const InterferenceFit& fit, FitBody body,
                                                 double r);

/// The same state at a point (x, z) of the cross-section, in Cartesian components
/// (sigma_x = sigma_r cos^2 + sigma_theta sin^2, tau_xz = (sigma_r - sigma_theta) sin cos, with
/// cos = x/r, sin = z/r): what a quarter model in the x-z plane samples.
PlaneStress interference_fit_cylinder_stress(const InterferenceFit& fit, FitBody body,
                                             PlanePoint at);

/// The contact pressure p > 0 of the sphere in the shell, above.
double interference_fit_sphere_pressure(const InterferenceFit& fit);

/// The spherical Lame state at radius R of `body` (R in [0, b] or [b, c]).
/// Throws InvalidInput for a bad fit or R outside the body.
SphereFitState interference_fit_sphere_state(const InterferenceFit& fit, FitBody body, double R);

/// The same state at (r, z) of the axisymmetric r-z model, R = (r^2 + z^2)^(1/2), in
/// cylindrical components (sigma_theta of the model is the spherical hoop stress).
AxiStress interference_fit_sphere_stress(const InterferenceFit& fit, FitBody body, AxiPoint at);

}  // namespace cs::oracles

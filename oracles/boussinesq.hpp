#pragma once
// Boussinesq's solution for a concentrated normal force on an elastic half-space: the full
// axisymmetric stress field, hoop stress included. The study uses it (with P = pi a^2 p) as the
// far-field traction of the axisymmetric problems (Eqs. 18-19, 41-42).
//
// Reference: J. Boussinesq (1885); K.L. Johnson, Contact Mechanics (1985), p. 51, as cited by
// the study.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// A compressive point force P on the surface z = 0 at r = 0 of an elastic half-space.
struct BoussinesqLoad {
  double P;   ///< normal force [force], > 0, pushing into the body
  double nu;  ///< Poisson's ratio, in [0, 0.5)
};

/// Study Eqs. 18-19 (Boussinesq; Johnson p. 51), with rho = (r^2 + z^2)^(1/2):
///   sigma_r     =  (P / 2pi) ((1 - 2nu) / r^2 (1 - z/rho) - 3 r^2 z / rho^5),
///   sigma_theta = -(P / 2pi) (1 - 2nu) (1 / r^2 (1 - z/rho) - z / rho^3),
///   sigma_z     = -(3P / 2pi) z^3 / rho^5,
///   tau_rz      = -(3P / 2pi) r z^2 / rho^5.
/// Evaluated scale-free, as (P / (2pi rho^2)) times functions of the direction cosines
/// r/rho and z/rho ((1/r^2)(1 - z/rho) = 1 / (rho^2 (1 + z/rho)), finite on the axis), so no
/// intermediate over- or underflows.
/// Domain: every finite point (r, z) != (0, 0) of the quadrant r, z >= 0 at which the stress
/// scale P / (2pi rho^2) does not overflow. Far points whose stress is below the smallest
/// double answer 0 (or a subnormal number): the exact value is that small.
/// Throws InvalidInput for P not positive, nu outside [0, 0.5), r < 0, z < 0, a non-finite
/// point, the load point (r, z) = (0, 0) itself, where the field is singular, or a point so
/// close to it that the stress overflows.
AxiStress boussinesq_stress(const BoussinesqLoad& load, AxiPoint at);

}  // namespace cs::oracles

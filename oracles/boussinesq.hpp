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
/// (1/r^2)(1 - z/rho) is evaluated as 1 / (rho (rho + z)), finite on the axis.
/// Throws InvalidInput for P not positive, nu outside [0, 0.5), r < 0, z < 0, or the load point
/// (r, z) = (0, 0) itself, where the field is singular.
AxiStress boussinesq_stress(const BoussinesqLoad& load, AxiPoint at);

}  // namespace cs::oracles

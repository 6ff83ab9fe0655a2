#pragma once
// Frictional contact patch tests, plane strain: an elastic block pressed by a flat block with a
// uniform pressure p and pulled sideways. While the applied shear tau stays below mu p the
// contact sticks and transmits tau exactly; a block that slides transmits exactly mu p. Either
// way the stress in the elastic block is uniform.
//
// Sign convention (docs/conventions.md, z into the elastic block): the traction on the block's
// contact surface is p in +z (pressure) and tau in +x, so sigma_z = -p and tau_xz = -tau.
//
// Axisymmetric counterpart: none. A uniform tau_rz is not an axisymmetric equilibrium state
// (d tau_rz / dr + d sigma_z / dz + tau_rz / r = tau_rz / r != 0), so a frictional patch test
// in the r-z plane has no uniform exact solution.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// Uniform pressure p and uniform shear tau < mu p: the contact sticks.
struct FrictionalPatchStick {
  double p;    ///< pressure [stress], > 0
  double tau;  ///< shear traction on the block in +x [stress], 0 <= tau < mu p
  double mu;   ///< Coulomb friction coefficient, in [0, 10]
};

/// Uniform pressure p with the block sliding in +x: the shear is mu p.
struct FrictionalPatchSlip {
  double p;   ///< pressure [stress], > 0
  double mu;  ///< Coulomb friction coefficient, in [0, 10]
};

/// sigma_x = 0, sigma_z = -p, tau_xz = -tau throughout the block (out of plane: -nu p).
/// Throws InvalidInput for p not positive, mu outside [0, 10], tau < 0 or not finite,
/// tau >= mu p ("Q >= mu P: the stick oracle needs Q < mu P", the tangential load against mu
/// times the normal one), a non-finite x or z < 0.
PlaneStress frictional_patch_stick_stress(const FrictionalPatchStick& load, PlanePoint at);

/// sigma_x = 0, sigma_z = -p, tau_xz = -mu p throughout the block. Throws InvalidInput for p
/// not positive, mu outside [0, 10], a non-finite x or z < 0.
PlaneStress frictional_patch_slip_stress(const FrictionalPatchSlip& load, PlanePoint at);

}  // namespace cs::oracles

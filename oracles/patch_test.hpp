#pragma once
// The contact patch tests (the study's Problems P and P'): a rigid flat block pressed by a
// uniform pressure p onto an elastic block of the same width, frictionless, perfectly aligned.
// The exact stress is uniform uniaxial compression.

#include "oracles/stress_state.hpp"

namespace cs::oracles {

/// The uniform pressure p > 0 applied to the top of the elastic block.
struct PatchTestLoad {
  double p;  ///< applied pressure [stress], > 0
};

/// Study Eq. 6 (plane strain): sigma_z = -p, sigma_x = tau_xz = 0 throughout the block (the
/// out-of-plane stress is -nu p). Throws InvalidInput for p not positive, a non-finite x, or
/// z < 0 (the block is 0 <= z <= h).
PlaneStress patch_test_plane_stress(const PatchTestLoad& load, PlanePoint at);

/// Study Eq. 8 (axisymmetric): sigma_z = -p, sigma_r = tau_rz = 0, and sigma_theta = 0 (the
/// lateral surface is free, so the state is uniaxial). Throws InvalidInput for p not positive,
/// r < 0 or z < 0.
AxiStress patch_test_axi_stress(const PatchTestLoad& load, AxiPoint at);

}  // namespace cs::oracles

#pragma once
// A built problem under a change of units: every length times L, every modulus and pressure
// times S (solver/model_scaling.hpp). Every normalized result (stresses over p, positions over
// a, penetrations over h, forces over the applied load) of the scaled setup is that of the
// original: the invariance of issue 14, which tests/suites/test_scaling_invariance.cpp proves.
//
// What scales, beyond the model (x' = L x; a force is S L per unit thickness, S L^2 per radian):
//   the contact pair's rigid profile              lengths x L
//   p                                             x S
//   length_unit, contact_half_width_a             x L
//   mesh_info: widths, depths, element sizes,     x L (counts unchanged)
//     S's refinement boxes
//   exact_pressure_over_p(x')                     = exact_pressure_over_p(x' / L)
//   exact_interface_force                         x the force factor
//   load_control->target_load                     x the force factor
// What does not: the quantities' exact values (normalized), the load steps, and the load
// control's advance delta and its first guess. The scaled model's callables call the original
// ones at x' / L and scale what they return (a prescribed displacement by L), so:
//   - a friction problem's load steps, which set the load state those callables read, apply to
//     the scaled model unchanged (its loads come out times S);
//   - the load control's delta stays in the original units (the support's scaled advance is
//     L delta), and so does delta_guess: the secant iterates are the original ones.
// The scaled setup therefore SHARES that state (load steps' loads, the load control's delta)
// with `setup`: run cases of the two one after the other, or build the setup twice.

#include "solver/model_scaling.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// The setup of `setup`'s problem in the units `scaling` defines (see the file comment).
/// Throws solver::ModelError for factors that are not positive and finite.
ProblemSetup scaled(const ProblemSetup& setup, const solver::ModelScaling& scaling);

}  // namespace cs::suites

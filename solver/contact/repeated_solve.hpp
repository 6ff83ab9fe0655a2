#pragma once
// When one contact solve repeats another, step for step and so bit for bit, on the same
// ContactAnalysis with the same loads: a caller that solves several settings on one model may
// then take the earlier result instead of solving again.
//
//   - The same settings, up to what the solve does not read: without friction the tangential
//     enforcement (LMP and PLM coincide, contact_options.hpp).
//   - PM after an AL solve that converged without augmenting: AL's first pass is the penalty
//     method's solve (augmented_lagrangian.cpp calls it), and PM reads neither FTOLN nor the
//     augmentation cap. With load steps or load control, `augmentations` must count every
//     solve the result stands for.

#include "solver/contact/contact_options.hpp"
#include "solver/contact/contact_result.hpp"

namespace cs::solver {

/// Whether solving with `settings` would give `earlier` (a result of earlier.settings), but for
/// its `settings` and timings.
bool repeats_solve(const ContactSettings& settings, const ContactResult& earlier);

}  // namespace cs::solver

#pragma once
// MPC (the study's IMC, ANSYS's internal multipoint constraint), as the study ran it: every
// constraint row found within the pinball at the start (every candidate) is tied to the target
// along the normal by the constraint equation g = 0 (the initial gap closed, KEYOPT(5) = 1 of
// the study), for the whole analysis: tension is allowed and nothing separates. Rows outside the
// pinball never act. One linear solve; no active set. Expected to be poor on the study's
// problems (its Table 2: 'u' throughout); kept faithful on purpose.

#include "solver/contact/active_set_solver.hpp"

namespace cs::solver {

/// Ties every row of the condensed problem (g = 0) and solves once.
AlgorithmOutcome solve_multipoint_constraint(const AlgorithmInput& input);

}  // namespace cs::solver

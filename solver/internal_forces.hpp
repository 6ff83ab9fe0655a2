#pragma once
// The internal nodal forces of a displacement field, f_int = K u = sum_e A_e^T K_e A_e u,
// assembled element by element (no global matrix). With the external loads f, the residual
// f_int - f at a node is the force the node receives from outside the bodies' elasticity: its
// contact force at a contact node, its reaction at a support. This is how another code's
// displacement field is checked for equilibrium on our model.

#include <Eigen/Core>

#include "solver/model.hpp"

namespace cs::solver {

/// K u for a (validated) model; `u` and the result hold 2 DOFs per node (x|r, z), the
/// mesh's node order. Throws ModelError for a degenerate element, as assembly does.
Eigen::VectorXd internal_forces(const Model& model, const Eigen::VectorXd& u);

}  // namespace cs::solver

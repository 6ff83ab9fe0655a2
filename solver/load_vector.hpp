#pragma once
// The global external force vector of a load case: edge tractions and pressures, point forces
// and body forces, as consistent nodal forces (per unit thickness | per radian).

#include <Eigen/Core>

#include "solver/model.hpp"

namespace cs::solver {

/// The global force vector (size 2 n_nodes, DOF 2 n + c) of `loads` on `model`.
/// `loads` must have been validated against the model (see validate(model, loads)).
Eigen::VectorXd assemble_load_vector(const Model& model, const LoadCase& loads);

}  // namespace cs::solver

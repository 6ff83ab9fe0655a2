#include "solver/dof_map.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "solver/model_error.hpp"

namespace cs::solver {

Eigen::VectorXd DofMap::evaluate(const Model& model) {
  const Mesh& mesh = model.mesh;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd value = Eigen::VectorXd::Constant(2 * mesh.n_nodes(), nan);
  for (const PrescribedDisplacement& p : model.prescribed) {
    const int c = static_cast<int>(p.component);
    for (int n : resolve_nodes(mesh, p.where)) {
      const double v = p.value(mesh.nodes[n]);
      if (!std::isfinite(v)) {
        throw ModelError(
            fmt::format("prescribed displacement on {}: value {} at node {} is not "
                        "finite",
                        p.where.describe(), v, n));
      }
      double& slot = value[2 * n + c];
      if (std::isnan(slot)) {
        slot = v;
      } else if (std::abs(slot - v) > 1e-12 * std::max(std::abs(slot), std::abs(v))) {
        throw ModelError(
            fmt::format("node {} component {}: prescribed twice with different "
                        "values ({} and {}, the latter by {})",
                        n, c, slot, v, p.where.describe()));
      }
    }
  }
  return value;
}

DofMap::DofMap(const Model& model) {
  const Eigen::VectorXd value = evaluate(model);
  const int n_dofs = static_cast<int>(value.size());
  equation_.assign(n_dofs, -1);
  constrained_index_.assign(n_dofs, -1);
  prescribed_ = Eigen::VectorXd::Zero(n_dofs);
  for (int d = 0; d < n_dofs; ++d) {
    if (std::isnan(value[d])) {
      equation_[d] = static_cast<int>(free_dofs_.size());
      free_dofs_.push_back(d);
    } else {
      constrained_index_[d] = static_cast<int>(constrained_dofs_.size());
      constrained_dofs_.push_back(d);
      prescribed_[d] = value[d];
    }
  }
}

void DofMap::update_prescribed_values(const Model& model) {
  const Eigen::VectorXd value = evaluate(model);
  if (value.size() != prescribed_.size()) {
    throw ModelError("DofMap::update_prescribed_values: the mesh changed size");
  }
  for (int d = 0; d < value.size(); ++d) {
    if (std::isnan(value[d]) != (equation_[d] >= 0)) {
      throw ModelError(
          fmt::format("DofMap::update_prescribed_values: DOF {} (node {}, component "
                      "{}) changed between free and prescribed; build a new DofMap",
                      d, d / 2, d % 2));
    }
    prescribed_[d] = std::isnan(value[d]) ? 0.0 : value[d];
  }
}

Eigen::VectorXd DofMap::restrict_to_free(const Eigen::VectorXd& global) const {
  Eigen::VectorXd out(n_free());
  for (int k = 0; k < n_free(); ++k)
    out[k] = global[free_dofs_[k]];
  return out;
}

Eigen::VectorXd DofMap::expand(const Eigen::VectorXd& u_free) const {
  Eigen::VectorXd u = prescribed_;
  for (int k = 0; k < n_free(); ++k)
    u[free_dofs_[k]] = u_free[k];
  return u;
}

}  // namespace cs::solver

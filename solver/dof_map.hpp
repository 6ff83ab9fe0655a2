#pragma once
// The map from global degrees of freedom to the equations of the reduced system.
//
// Global DOF of node n, component c (0 = x|r, 1 = z) is 2 n + c. Prescribed displacements are
// eliminated: the reduced system K_ff u_f = f_f - K_fc u_c is over the free DOFs only, numbered
// in increasing global order (equation k <-> free_dofs()[k]). Contact adds its terms in this
// reduced space (see solver/linear_static.hpp).

#include <vector>

#include <Eigen/Core>

#include "solver/analysis_type.hpp"
#include "solver/model.hpp"

namespace cs::solver {

class DofMap {
 public:
  /// Builds the map from the prescribed displacements of a validated model and evaluates their
  /// values. Throws ModelError if one DOF is prescribed twice with different values.
  explicit DofMap(const Model& model);

  int n_dofs() const { return static_cast<int>(equation_.size()); }
  int n_free() const { return static_cast<int>(free_dofs_.size()); }
  int n_constrained() const { return static_cast<int>(constrained_dofs_.size()); }

  /// Equation index of global DOF `dof`, or -1 if it is prescribed.
  int equation(int dof) const { return equation_[dof]; }
  int equation(int node, Component c) const { return equation_[global_dof(node, c)]; }
  bool is_free(int dof) const { return equation_[dof] >= 0; }

  /// Global DOF -> equation index or -1 (size n_dofs()).
  const std::vector<int>& equations() const { return equation_; }
  /// Equation index -> global DOF (size n_free()), increasing.
  const std::vector<int>& free_dofs() const { return free_dofs_; }
  /// The prescribed global DOFs, increasing. Row k of the constrained-rows stiffness
  /// (see assembly.hpp) is DOF constrained_dofs()[k].
  const std::vector<int>& constrained_dofs() const { return constrained_dofs_; }
  /// Index of `dof` in constrained_dofs(), or -1 if it is free.
  int constrained_index(int dof) const { return constrained_index_[dof]; }

  /// Global vector of prescribed values: u at prescribed DOFs, 0 at free DOFs.
  const Eigen::VectorXd& prescribed_values() const { return prescribed_; }

  /// Re-evaluates the prescribed values from `model` (whose constraints must select the same
  /// DOFs as when the map was built; throws ModelError otherwise).
  void update_prescribed_values(const Model& model);

  /// The free entries of a global vector (size n_free()).
  Eigen::VectorXd restrict_to_free(const Eigen::VectorXd& global) const;
  /// The global vector with free entries `u_free` and prescribed entries prescribed_values().
  Eigen::VectorXd expand(const Eigen::VectorXd& u_free) const;

 private:
  /// Evaluates the constraints: per global DOF, its value (NaN where free).
  static Eigen::VectorXd evaluate(const Model& model);

  std::vector<int> equation_;
  std::vector<int> free_dofs_;
  std::vector<int> constrained_dofs_;
  std::vector<int> constrained_index_;
  Eigen::VectorXd prescribed_;
};

}  // namespace cs::solver

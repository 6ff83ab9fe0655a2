#pragma once
// Assembly of the global stiffness in the reduced (free-DOF) space, by element, into a sparsity
// pattern computed once.
//
// The pattern of K_ff and, for every element, the position of each of its element-matrix
// entries in K_ff's value array (the scatter map) are computed when the Assembler is built.
// Assembly then only computes element matrices and adds them at known positions; changing
// materials or coordinates keeps the pattern, so the linear solver's symbolic analysis is
// reused (see LinearSolver::factorize).

#include <vector>

#include <Eigen/SparseCore>

#include "solver/dof_map.hpp"
#include "solver/elements/element_kinematics.hpp"
#include "solver/model.hpp"

namespace cs::solver {

/// The stiffness matrices of a model, split by the DofMap.
struct StiffnessMatrices {
  /// K_ff: the free-free block, LOWER TRIANGLE only (row >= column), compressed column storage
  /// with sorted rows: what CHOLMOD and SimplicialLDLT<..., Lower> read. n_free x n_free.
  Eigen::SparseMatrix<double> K_ff;
  /// K_cg: the rows of the full stiffness at the prescribed DOFs (row k is DOF
  /// DofMap::constrained_dofs()[k]), every global column. n_constrained x n_dofs. Gives the
  /// load correction K_fc u_c = (K_cg^T u_c) restricted to free DOFs, and the reactions.
  Eigen::SparseMatrix<double, Eigen::RowMajor> K_cg;
};

class Assembler {
 public:
  /// Computes the pattern of K_ff and the scatter map of every element. `model` (validated)
  /// and `dofs` must outlive the Assembler and keep their mesh and prescribed DOF set.
  Assembler(const Model& model, const DofMap& dofs);

  /// Computes every element stiffness and assembles K_ff (values into the fixed pattern) and
  /// K_cg. Throws ModelError for an inverted or degenerate element (named, with its body). The
  /// element matrices are computed on a spare core too when one is idle
  /// (solver/spare_cores.hpp) and added in element order, so the sums never depend on it.
  void assemble(StiffnessMatrices& out) const;

  /// Nonzeros of the lower triangle of K_ff.
  long nnz() const { return static_cast<long>(inner_.size()); }

 private:
  /// The scatter map of elements [first, last).
  void map_elements(int first, int last);
  /// Adds element e's matrix K_e to K_ff's `values` and its prescribed DOFs' rows to
  /// `constrained`.
  void add_element(int e, const ElementMatrix& K_e, double* values,
                   std::vector<Eigen::Triplet<double>>& constrained) const;

  const Model& model_;
  const DofMap& dofs_;
  int pairs_per_element_ = 0;  ///< nd (nd + 1) / 2 with nd = 2 n_element_nodes
  std::vector<int> outer_;     ///< column starts of K_ff (n_free + 1)
  std::vector<int> inner_;     ///< row indices of K_ff
  std::vector<int> scatter_;   ///< per element and local pair (i >= j): value index or -1
};

}  // namespace cs::solver

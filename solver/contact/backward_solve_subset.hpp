#pragma once
// The backward solve L^T x = y of a CHOLMOD supernodal factor, restricted to the entries some
// columns need. Solving from the last supernode down, x_j reads x_i for every row i of L's column
// j, and those rows are j's ancestors in the elimination tree: the entries of a few columns need
// only the supernodes on their paths to the root. With a nested-dissection ordering, the paths of
// a surface's columns cross a small part of the factor, so a displacement wanted only along the
// contact and sampled surfaces costs that part of a backward solve, not all of it.

#include <vector>

#include <cholmod.h>

namespace cs::solver {

class BackwardSolveSubset {
 public:
  /// The supernodes of `L` (supernodal, simplicial ones are refused with std::invalid_argument)
  /// holding any of `columns` (factor columns, in the factor's order) and their ancestors.
  BackwardSolveSubset(const cholmod_factor& L, const std::vector<int>& columns);

  /// x := L^{-T} x on the subset's columns, the others left as they are. Each supernode is
  /// solved by the BLAS calls of CHOLMOD's own supernodal solve of one right-hand side (x1 -=
  /// L2^T x2, then L1^T x1 = x1), so those entries are bit for bit cholmod_solve(CHOLMOD_Lt)'s.
  /// `x` holds L->n entries; `L` is the factor the subset was made for.
  void solve(const cholmod_factor& L, double* x) const;

  /// The factor columns whose entries solve() gives, increasing.
  const std::vector<int>& columns() const { return columns_; }

 private:
  std::vector<int> supernodes_;  ///< decreasing: the order of a backward solve
  std::vector<int> columns_;
};

}  // namespace cs::solver

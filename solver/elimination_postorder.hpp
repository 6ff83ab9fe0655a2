#pragma once
// A postorder of the elimination tree of a leading block, computed before the symbolic analysis.
//
// The condensation eliminates the contact DOFs last, and CHOLMOD's own postorder of the whole
// tree may move an interior subtree behind a contact DOF (it visits the heavier child last);
// putting them back took a second symbolic analysis. Postordering the interior here, with the
// contact DOFs left at the end, gives an order of the same fill that CHOLMOD analyzes once,
// without postordering again.

#include <vector>

#include <Eigen/SparseCore>

namespace cs::solver {

/// `perm` (perm[k] = the equation eliminated k-th, a permutation of A's equations) with its
/// first `n_leading` entries reordered by a postorder of the elimination tree of the leading
/// block A(perm[0..n_leading), perm[0..n_leading)), and its other entries unchanged, at the end.
/// Children are visited in increasing position, roots too. The elimination tree is Liu's: the
/// parent of column j is the first row i > j with L(i, j) != 0, found from the pattern of the
/// lower triangle `A_lower` with path compression. Any postorder of the tree is an equivalent
/// ordering: the factor has the same nonzeros and operation count.
std::vector<int> postordered_leading_block(const Eigen::SparseMatrix<double>& A_lower,
                                           const std::vector<int>& perm, int n_leading);

}  // namespace cs::solver

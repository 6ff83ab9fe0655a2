#pragma once
// The principal submatrix of a symmetric sparse matrix stored as its lower triangle: the rows and
// columns of some equations, renumbered.

#include <vector>

#include <Eigen/SparseCore>

namespace cs::solver {

/// The lower triangle of A's principal submatrix on the equations `global` (its equation l is
/// A's global[l]; global holds distinct equations of A), CSC with sorted rows. A_lower: A's
/// lower triangle, CSC.
Eigen::SparseMatrix<double> principal_lower(const Eigen::SparseMatrix<double>& A_lower,
                                            const std::vector<int>& global);

}  // namespace cs::solver

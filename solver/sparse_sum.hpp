#pragma once
// The sum of a large sparse matrix and one of a few entries, as Eigen's `K + D` gives it.

#include <Eigen/SparseCore>

namespace cs::solver {

/// S = K + D, for two matrices of one size (CSC, rows sorted in each column): S holds the
/// entries of either, s_ij = k_ij + d_ij, where a matrix has no entry its value taken as 0. The
/// values are those of Eigen's `K + D` bit for bit, signed zeros included (k + 0.0, 0.0 + d),
/// and S is compressed. Eigen evaluates `K + D` through its generic sparse assignment; this
/// copies K column by column and merges only the columns where D has entries, which for a
/// fine-mesh stiffness (40 million entries) and the contact DOFs' few takes a fraction of the
/// time. Throws std::invalid_argument when the sizes differ.
Eigen::SparseMatrix<double> sparse_sum(const Eigen::SparseMatrix<double>& K,
                                       const Eigen::SparseMatrix<double>& D);

}  // namespace cs::solver

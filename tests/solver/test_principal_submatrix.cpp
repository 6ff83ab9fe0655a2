// principal_lower: the lower triangle of a principal submatrix, checked against the dense
// matrix's rows and columns picked by hand.

#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "solver/principal_submatrix.hpp"

namespace cs::solver::test_principal_submatrix {
namespace {

/// A symmetric 40 x 40 matrix with a scattered pattern (entry (i, j) when (i * j) % 7 < 3 or
/// i == j), values 1 + i + 0.01 j for i >= j.
Eigen::MatrixXd scattered_symmetric() {
  const int n = 40;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = j; i < n; ++i) {
      if (i == j || (i * j) % 7 < 3)
        A(i, j) = A(j, i) = 1.0 + i + 0.01 * j;
    }
  }
  return A;
}

// Requirement (issue 27): a side's submatrix holds exactly A's entries among its equations,
// renumbered in the order given (not increasing), as a lower triangle with sorted rows. Fails if
// an entry is dropped, placed above the diagonal, or left unsorted.
TEST(PrincipalSubmatrix, HoldsTheEntriesOfItsEquationsInTheGivenOrder) {
  const Eigen::MatrixXd A = scattered_symmetric();
  const Eigen::SparseMatrix<double> A_lower =
      A.triangularView<Eigen::Lower>().toDenseMatrix().sparseView();
  const std::vector<int> global = {3, 17, 5, 39, 0, 22, 8, 31, 12};  // not increasing
  const Eigen::SparseMatrix<double> B = principal_lower(A_lower, global);
  const int m = static_cast<int>(global.size());
  ASSERT_EQ(B.rows(), m);
  ASSERT_TRUE(B.isCompressed());
  Eigen::MatrixXd expected(m, m);
  for (int a = 0; a < m; ++a) {
    for (int b = 0; b < m; ++b)
      expected(a, b) = a >= b ? A(global[a], global[b]) : 0.0;
  }
  EXPECT_EQ(Eigen::MatrixXd(B), expected);
  for (int j = 0; j < m; ++j) {
    for (int k = B.outerIndexPtr()[j] + 1; k < B.outerIndexPtr()[j + 1]; ++k)
      EXPECT_LT(B.innerIndexPtr()[k - 1], B.innerIndexPtr()[k]) << "column " << j;
  }
}

}  // namespace
}  // namespace cs::solver::test_principal_submatrix

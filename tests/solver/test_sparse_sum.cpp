// sparse_sum: K + D, checked against Eigen's own `K + D` to the bit.

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include "solver/sparse_sum.hpp"
#include "support/same_bits.hpp"

namespace cs::solver::test_sparse_sum {
namespace {

using cs::testing::expect_same_bits;
using SparseMatrix = Eigen::SparseMatrix<double>;

/// A 30 x 30 lower triangle with a scattered pattern (entry (i, j) when i == j or
/// (i * j + i) % 5 < 2), column 7 left empty, and one entry -0.0 (at (9, 3)).
SparseMatrix scattered_lower() {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < 30; ++j) {
    for (int i = j; i < 30; ++i) {
      if (j != 7 && (i == j || (i * j + i) % 5 < 2))
        t.emplace_back(i, j, i == 9 && j == 3 ? -0.0 : 1.0 / (1.0 + i + 3.0 * j));
    }
  }
  SparseMatrix K(30, 30);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

/// A few entries, some on K's pattern and some off it (in the empty column, before and after
/// a column's entries, and on the -0.0).
SparseMatrix few_entries() {
  const std::vector<Eigen::Triplet<double>> t = {
      {0, 0, 0.3},    {4, 0, 1.0 / 3.0}, {7, 7, 2.0},   {8, 7, -0.7},       {9, 3, 0.0},
      {29, 3, 1e-17}, {12, 12, 5.0},     {13, 12, 0.1}, {29, 29, 1.0 / 7.0}};
  SparseMatrix D(30, 30);
  D.setFromTriplets(t.begin(), t.end());
  return D;
}

// Requirement (issue 27): the contact DOFs' Delta added without Eigen's generic evaluation gives
// Eigen's K + D to the bit: the union of the patterns, each sum k + d, signed zeros as Eigen
// gives them (-0.0 + 0.0 is +0.0). Fails on a dropped or doubled entry, an unsorted column, or a
// K value copied where Eigen adds 0.0.
TEST(SparseSum, IsEigensSumToTheBit) {
  const SparseMatrix K = scattered_lower();
  const SparseMatrix D = few_entries();
  SparseMatrix eigen = K + D;
  eigen.makeCompressed();
  expect_same_bits(sparse_sum(K, D), eigen);
  EXPECT_FALSE(std::signbit(sparse_sum(K, SparseMatrix(30, 30)).coeff(9, 3)));

  // K not compressed (room left in its columns): the same sum.
  SparseMatrix loose = K;
  loose.reserve(Eigen::VectorXi::Constant(30, 3));
  ASSERT_FALSE(loose.isCompressed());
  expect_same_bits(sparse_sum(loose, D), eigen);
}

TEST(SparseSum, MatricesOfTwoSizesAreRefused) {
  EXPECT_THROW(sparse_sum(scattered_lower(), SparseMatrix(30, 29)), std::invalid_argument);
}

}  // namespace
}  // namespace cs::solver::test_sparse_sum

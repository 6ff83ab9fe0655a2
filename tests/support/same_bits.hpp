#pragma once
// Whether two sparse matrices are the same to the bit: one pattern, one set of value bits.

#include <cstring>

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

namespace cs::testing {

/// Expects `a` and `b` (compressed) to hold the same pattern and the same value bits, signed
/// zeros included: what a change of schedule or of summation code must leave alone.
template <int Options>
void expect_same_bits(const Eigen::SparseMatrix<double, Options>& a,
                      const Eigen::SparseMatrix<double, Options>& b) {
  ASSERT_TRUE(a.isCompressed());
  ASSERT_TRUE(b.isCompressed());
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.cols(), b.cols());
  ASSERT_EQ(a.nonZeros(), b.nonZeros());
  const auto n = static_cast<std::size_t>(a.nonZeros());
  const auto outer = static_cast<std::size_t>(a.outerSize()) + 1;
  EXPECT_EQ(std::memcmp(a.outerIndexPtr(), b.outerIndexPtr(), outer * sizeof(int)), 0);
  EXPECT_EQ(std::memcmp(a.innerIndexPtr(), b.innerIndexPtr(), n * sizeof(int)), 0);
  EXPECT_EQ(std::memcmp(a.valuePtr(), b.valuePtr(), n * sizeof(double)), 0);
}

}  // namespace cs::testing

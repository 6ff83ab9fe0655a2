// The METIS ordering is a function of the matrix alone: the same on every call, from any
// thread, while other threads order other matrices. METIS draws from one random generator for
// the whole process, so concurrent calls interleaved their draws and returned other orderings;
// those factor the same matrix with other round-off, and the load-controlled S cases of a run
// with two workers then moved in the 7th digit from run to run.

#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "solver/fill_reducing_ordering.hpp"

namespace cs::solver {
namespace {

/// The lower triangle of the 5-point Laplacian pattern of an n x n grid, two DOFs per node.
Eigen::SparseMatrix<double> grid_lower(int n) {
  std::vector<Eigen::Triplet<double>> t;
  const auto node = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int c = 0; c < 2; ++c) {
        const int a = 2 * node(i, j) + c;
        t.emplace_back(a, a, 4.0);
        if (i > 0)
          t.emplace_back(a, 2 * node(i - 1, j) + c, -1.0);
        if (j > 0)
          t.emplace_back(a, 2 * node(i, j - 1) + c, -1.0);
      }
    }
  }
  Eigen::SparseMatrix<double> A(2 * n * n, 2 * n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A.triangularView<Eigen::Lower>();
}

std::vector<int> node_groups(int n_equations) {
  std::vector<int> g(n_equations);
  for (int i = 0; i < n_equations; ++i)
    g[i] = i / 2;
  return g;
}

// Requirement: metis_quotient_ordering gives the serial ordering on every call of several
// threads that order different matrices at the same time.
TEST(FillReducingOrdering, MetisOrderingIsTheSameFromConcurrentThreads) {
  const std::vector<int> sizes{90, 110, 130, 150};
  std::vector<Eigen::SparseMatrix<double>> matrices;
  std::vector<std::vector<int>> serial;
  for (const int n : sizes) {
    matrices.push_back(grid_lower(n));
    serial.push_back(metis_quotient_ordering(matrices.back(), node_groups(matrices.back().rows())));
  }
  constexpr int kRepeats = 6;
  std::vector<int> differing(sizes.size(), 0);
  {
    std::vector<std::jthread> threads;
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      threads.emplace_back([&, k] {
        for (int r = 0; r < kRepeats; ++r) {
          const auto perm = metis_quotient_ordering(matrices[k], node_groups(matrices[k].rows()));
          differing[k] += perm != serial[k] ? 1 : 0;
        }
      });
    }
  }
  for (std::size_t k = 0; k < sizes.size(); ++k)
    EXPECT_EQ(differing[k], 0) << sizes[k] << " x " << sizes[k] << " grid";
}

}  // namespace
}  // namespace cs::solver

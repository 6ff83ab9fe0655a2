// The METIS ordering is a function of the matrix alone: the same on every call, from any
// thread, while other threads order other matrices. METIS draws from one random generator for
// the whole process, so concurrent calls interleaved their draws and returned other orderings;
// those factor the same matrix with other round-off, and the load-controlled S cases of a run
// with two workers then moved in the 7th digit from run to run. A program linked with the
// solver gives each thread a generator of its own (solver/per_thread_rand.hpp), so the calls
// need not take turns.

#include <atomic>
#include <cstdlib>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "solver/fill_reducing_ordering.hpp"
#include "solver/per_thread_rand.hpp"

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

/// The first draws after srand(seed) on this thread.
std::vector<int> draws(unsigned seed, int count) {
  srand(seed);
  std::vector<int> out;
  for (int k = 0; k < count; ++k)
    out.push_back(rand());
  return out;
}

// Requirement: this program draws rand() per thread, with glibc's numbers (glibc's first draw
// after srand(1) is 1804289383, as it is before any srand), and the calls into METIS take no
// turn.
TEST(PerThreadRand, AProgramLinkedWithTheSolverDrawsPerThreadWithGlibcsNumbers) {
  ASSERT_TRUE(rand_is_per_thread());
  EXPECT_FALSE(metis_turn().owns_lock());
  int first = 0;
  std::jthread([&] { first = rand(); }).join();  // a new thread's generator, never seeded
  EXPECT_EQ(first, 1804289383);
  EXPECT_EQ(draws(1, 1).front(), 1804289383);
}

// Requirement: two threads seeded alike draw the same numbers while they draw at once, each
// what it draws alone (METIS's draws while another thread orders).
TEST(PerThreadRand, AThreadsDrawsAreItsOwn) {
  const std::vector<int> alone = draws(4321, 20000);
  std::atomic<int> ready = 0;
  std::vector<int> a, b;
  {
    const auto both = [&](std::vector<int>& out) {
      ++ready;
      while (ready < 2) {
      }
      out = draws(4321, 20000);
    };
    std::jthread ta(both, std::ref(a)), tb(both, std::ref(b));
  }
  EXPECT_EQ(a, alone);
  EXPECT_EQ(b, alone);
}

}  // namespace
}  // namespace cs::solver

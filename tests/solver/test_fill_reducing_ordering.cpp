// The METIS ordering is a function of the matrix alone: the same on every call, from any
// thread, while other threads order other matrices. METIS draws from one random generator for
// the whole process, so concurrent calls interleaved their draws and returned other orderings;
// those factor the same matrix with other round-off, and the load-controlled S cases of a run
// with two workers then moved in the 7th digit from run to run. A program linked with the
// solver gives each thread a generator of its own (solver/per_thread_rand.hpp), so the calls
// need not take turns.

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdlib>
#include <optional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>

#include "solver/fill_reducing_ordering.hpp"
#include "solver/per_thread_rand.hpp"
#include "solver/spare_cores.hpp"

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

// Requirement: equations with a negative group are left out, as if their rows and columns were
// deleted: the ordering is the principal submatrix's, in the whole matrix's numbering.
TEST(FillReducingOrdering, EquationsWithANegativeGroupAreLeftOut) {
  const int side = 60;
  const Eigen::SparseMatrix<double> A = grid_lower(side);
  const int n = static_cast<int>(A.rows());
  std::vector<int> groups = node_groups(n);
  std::vector<int> kept;  // sub index -> equation
  std::vector<int> index(n, -1);
  for (int eq = 0; eq < n; ++eq) {
    if (eq % 7 == 3 || eq >= n - 2 * side) {  // scattered DOFs and the last row of nodes
      groups[eq] = -1;
    } else {
      index[eq] = static_cast<int>(kept.size());
      kept.push_back(eq);
    }
  }
  std::vector<Eigen::Triplet<double>> t;
  std::vector<int> sub_groups;
  for (int eq : kept)
    sub_groups.push_back(groups[eq]);
  for (int j = 0; j < n; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      if (index[j] >= 0 && index[it.row()] >= 0)
        t.emplace_back(index[it.row()], index[j], it.value());
    }
  }
  Eigen::SparseMatrix<double> sub(static_cast<int>(kept.size()), static_cast<int>(kept.size()));
  sub.setFromTriplets(t.begin(), t.end());
  std::vector<int> expected;
  for (int k : metis_quotient_ordering(sub, sub_groups))
    expected.push_back(kept[k]);
  EXPECT_EQ(metis_quotient_ordering(A, groups), expected);
}

// quotient_bisection: fails if an entry couples the two sides, a side is empty or much smaller
// than the other, a node's DOFs lie on different sides, the separator is not a thin line of the
// grid, or an equation left out gets a side.
TEST(FillReducingOrdering, ABisectionLeavesNoEntryBetweenItsSides) {
  const int side = 60;
  const Eigen::SparseMatrix<double> A = grid_lower(side);
  const int n = static_cast<int>(A.rows());
  std::vector<int> groups = node_groups(n);
  for (int eq = n - 2 * side; eq < n; ++eq)
    groups[eq] = -1;  // the last row of nodes left out
  const std::vector<int> part = quotient_bisection(A, groups);
  ASSERT_EQ(static_cast<int>(part.size()), n);
  std::array<int, 4> count{};  // left out, side 0, side 1, separator
  for (int eq = 0; eq < n; ++eq) {
    ++count[part[eq] + 1];
    EXPECT_EQ(part[eq] < 0, groups[eq] < 0) << "equation " << eq;
    if (eq % 2 == 1) {
      EXPECT_EQ(part[eq], part[eq - 1]) << "node " << eq / 2;
    }
  }
  for (int j = 0; j < n; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const int a = part[it.row()], b = part[j];
      EXPECT_FALSE((a == 0 && b == 1) || (a == 1 && b == 0)) << it.row() << ", " << j;
    }
  }
  EXPECT_EQ(count[0], 2 * side);
  EXPECT_GT(count[1], count[2] / 2);
  EXPECT_GT(count[2], count[1] / 2);
  EXPECT_LE(count[3], 2 * 2 * side);  // at most two grid lines of nodes
}

/// The nonzeros of the Cholesky factor of A (lower triangle given) in the order perm, or, with an
/// empty perm, in CHOLMOD's own METIS ordering of A's graph.
double factor_nonzeros(const Eigen::SparseMatrix<double>& A_lower, std::vector<int> perm) {
  cholmod_common c;
  cholmod_start(&c);
  c.nmethods = 1;
  c.method[0].ordering = perm.empty() ? CHOLMOD_METIS : CHOLMOD_GIVEN;
  c.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse view = Eigen::viewAsCholmod(A_lower.selfadjointView<Eigen::Lower>());
  cholmod_factor* L =
      cholmod_analyze_p(&view, perm.empty() ? nullptr : perm.data(), nullptr, 0, &c);
  const double lnz = L != nullptr ? c.lnz : -1.0;
  cholmod_free_factor(&L, &c);
  cholmod_finish(&c);
  return lnz;
}

bool is_permutation_of_0_to(const std::vector<int>& perm, int n) {
  std::vector<int> sorted = perm;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < n; ++k) {
    if (k >= static_cast<int>(sorted.size()) || sorted[k] != k)
      return false;
  }
  return static_cast<int>(sorted.size()) == n;
}

// Requirement: from kSplitFrom vertices on, the first separator is taken outside METIS and the
// two parts are ordered by two METIS calls; the ordering is a permutation, the same whether or
// not a spare core orders the second part at once, and it fills the factor about as little as
// METIS's own nested dissection of the whole graph.
TEST(FillReducingOrdering, ASplitOrderingIsTheSameOnOneCoreOrTwoAndFillsLikeMetis) {
  const int side = 450;  // 202,500 nodes
  ASSERT_GE(side * side, kSplitFrom);
  const Eigen::SparseMatrix<double> A = grid_lower(side);
  const std::vector<int> groups = node_groups(static_cast<int>(A.rows()));
  ASSERT_EQ(spare_cores(), 0);
  const std::vector<int> alone = metis_quotient_ordering(A, groups);
  std::vector<int> with_a_spare_core;
  {
    const CoreLoan loan(1);
    with_a_spare_core = metis_quotient_ordering(A, groups);
    EXPECT_EQ(spare_cores(), 1);  // returned after use
  }
  EXPECT_EQ(spare_cores(), 0);
  ASSERT_TRUE(is_permutation_of_0_to(alone, static_cast<int>(A.rows())));
  EXPECT_EQ(with_a_spare_core, alone);
  const double split_fill = factor_nonzeros(A, alone);
  const double metis_fill = factor_nonzeros(A, {});
  ASSERT_GT(metis_fill, 0.0);
  EXPECT_LT(split_fill, 1.10 * metis_fill) << split_fill << " vs " << metis_fill;
}

// Requirement: a core is borrowed only while the pool holds one, and each loan is taken back.
TEST(SpareCores, ACoreIsBorrowedOnlyFromTheLoanedPool) {
  ASSERT_EQ(spare_cores(), 0);
  {
    const SpareCore none;
    EXPECT_FALSE(none);
  }
  {
    CoreLoan loan(1);
    {
      const SpareCore first;
      const SpareCore second;
      EXPECT_TRUE(first);
      EXPECT_FALSE(second);
      EXPECT_EQ(spare_cores(), 0);
    }
    EXPECT_EQ(spare_cores(), 1);
    loan.lend(2);
    EXPECT_EQ(spare_cores(), 3);
  }
  EXPECT_EQ(spare_cores(), 0);
  {
    // A loan taken back while its core is borrowed: the core comes back to an empty pool.
    std::optional<CoreLoan> loan(std::in_place, 1);
    {
      const SpareCore borrowed;
      ASSERT_TRUE(borrowed);
      loan.reset();
      EXPECT_EQ(spare_cores(), 0);
    }
    EXPECT_EQ(spare_cores(), 0);
  }
  {
    // lend_up_to lends the difference, and never takes back.
    CoreLoan loan;
    loan.lend_up_to(2);
    EXPECT_EQ(spare_cores(), 2);
    loan.lend_up_to(1);
    EXPECT_EQ(spare_cores(), 2);
    loan.lend_up_to(3);
    EXPECT_EQ(spare_cores(), 3);
  }
  EXPECT_EQ(spare_cores(), 0);
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

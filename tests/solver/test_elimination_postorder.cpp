// The interior postorder that lets CHOLMOD analyze the condensation's order once: a permutation
// that leaves the trailing entries where they were, visits every subtree of the leading block's
// elimination tree contiguously (a postorder), and fills the factor exactly as the order it
// came from (an equivalent ordering).

#include <algorithm>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/CholmodSupport>

#include "solver/elimination_postorder.hpp"

namespace cs::solver {
namespace {

/// The lower triangle of the 9-point pattern of two blocks of side x side nodes (two DOFs each),
/// joined only through the DOFs of one row of `link` nodes: two bodies touching at a surface.
Eigen::SparseMatrix<double> two_bodies_lower(int side, int& n_link_dofs) {
  const int body = 2 * side * side;
  n_link_dofs = 2 * side;
  const int n = 2 * body + n_link_dofs;
  std::vector<Eigen::Triplet<double>> t;
  const auto couple = [&t](int a, int b) { t.emplace_back(std::max(a, b), std::min(a, b), -1.0); };
  for (int b = 0; b < 2; ++b) {
    for (int i = 0; i < side; ++i) {
      for (int j = 0; j < side; ++j) {
        for (int c = 0; c < 2; ++c) {
          const int a = b * body + 2 * (i * side + j) + c;
          t.emplace_back(a, a, 8.0);
          if (i > 0)
            couple(a, a - 2 * side);
          if (j > 0)
            couple(a, a - 2);
          if (i > 0 && j > 0)
            couple(a, a - 2 * side - 2);
          const bool at_surface = b == 0 ? i == side - 1 : i == 0;
          if (at_surface)
            couple(a, 2 * body + 2 * j + c);  // the link node above or below
        }
      }
    }
  }
  for (int k = 0; k < n_link_dofs; ++k)
    t.emplace_back(2 * body + k, 2 * body + k, 8.0);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// CHOLMOD's nonzeros of L for A in the order perm, without a postorder of its own.
double nonzeros_without_postorder(const Eigen::SparseMatrix<double>& A_lower,
                                  std::vector<int> perm) {
  cholmod_common c;
  cholmod_start(&c);
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_GIVEN;
  c.postorder = 0;
  cholmod_sparse v = Eigen::viewAsCholmod(A_lower.selfadjointView<Eigen::Lower>());
  cholmod_factor* L = cholmod_analyze_p(&v, perm.data(), nullptr, 0, &c);
  const double lnz = L != nullptr ? c.lnz : -1.0;
  cholmod_free_factor(&L, &c);
  cholmod_finish(&c);
  return lnz;
}

/// CHOLMOD's elimination tree of A(perm, perm).
std::vector<int> cholmod_tree(const Eigen::SparseMatrix<double>& A_lower,
                              const std::vector<int>& perm) {
  const int n = static_cast<int>(A_lower.rows());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(n);
  for (int k = 0; k < n; ++k)
    P.indices()[perm[k]] = k;  // equation perm[k] goes to position k
  Eigen::SparseMatrix<double> permuted;
  permuted = A_lower.selfadjointView<Eigen::Lower>().twistedBy(P);
  const Eigen::SparseMatrix<double> upper = permuted.triangularView<Eigen::Upper>();
  cholmod_common c;
  cholmod_start(&c);
  cholmod_sparse v = Eigen::viewAsCholmod(upper.selfadjointView<Eigen::Upper>());
  std::vector<int> parent(n);
  EXPECT_TRUE(cholmod_etree(&v, parent.data(), &c));
  cholmod_finish(&c);
  return parent;
}

/// Whether, in the forest of the first m positions of the tree (a node whose parent is at m or
/// later is a root), every node's subtree occupies the positions just before it.
bool is_postorder(const std::vector<int>& parent, int m) {
  std::vector<int> size(m, 1), first(m);
  std::iota(first.begin(), first.end(), 0);
  for (int k = 0; k < m; ++k) {
    if (parent[k] >= 0 && parent[k] < m) {
      if (parent[k] <= k)
        return false;
      size[parent[k]] += size[k];
      first[parent[k]] = std::min(first[parent[k]], first[k]);
    }
  }
  for (int k = 0; k < m; ++k) {
    if (first[k] != k - size[k] + 1)
      return false;
  }
  return true;
}

// Requirement: the leading block comes back postordered, the trailing entries unchanged, with
// the same factor fill as the order given.
TEST(EliminationPostorder, PostordersTheInteriorKeepsTheTailAndTheFill) {
  int n_link = 0;
  const Eigen::SparseMatrix<double> A = two_bodies_lower(40, n_link);
  const int n = static_cast<int>(A.rows());
  const int n_interior = n - n_link;
  // The two bodies' DOFs interleaved (each body in its own natural order), which no postorder
  // is: the two bodies are subtrees of their own.
  std::vector<int> perm;
  const int body = n_interior / 2;
  for (int k = 0; k < body; ++k) {
    perm.push_back(k);
    perm.push_back(body + k);
  }
  for (int k = n_interior; k < n; ++k)
    perm.push_back(k);  // the link DOFs last, as the condensation's contact DOFs

  const std::vector<int> post = postordered_leading_block(A, perm, n_interior);
  std::vector<int> sorted = post;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(n);
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity);
  EXPECT_TRUE(std::equal(perm.begin() + n_interior, perm.end(), post.begin() + n_interior));
  EXPECT_FALSE(is_postorder(cholmod_tree(A, perm), n_interior));
  EXPECT_TRUE(is_postorder(cholmod_tree(A, post), n_interior));
  EXPECT_EQ(nonzeros_without_postorder(A, post), nonzeros_without_postorder(A, perm));
}

}  // namespace
}  // namespace cs::solver

#include "solver/elimination_postorder.hpp"

#include <algorithm>

namespace cs::solver {
namespace {

/// For each position k < n, the positions j < k adjacent to it (CSR: start[k] .. start[k+1]).
struct EarlierNeighbours {
  std::vector<long> start;
  std::vector<int> index;
};

EarlierNeighbours earlier_neighbours(const Eigen::SparseMatrix<double>& A_lower,
                                     const std::vector<int>& position, int n) {
  EarlierNeighbours e;
  e.start.assign(n + 1, 0);
  const auto each_pair = [&](auto&& visit) {
    for (int c = 0; c < A_lower.outerSize(); ++c) {
      const int q = position[c];
      if (q < 0)
        continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(A_lower, c); it; ++it) {
        const int p = position[it.row()];
        if (p >= 0 && p != q)
          visit(std::max(p, q), std::min(p, q));
      }
    }
  };
  each_pair([&](int later, int) { ++e.start[later + 1]; });
  for (int k = 0; k < n; ++k)
    e.start[k + 1] += e.start[k];
  e.index.resize(e.start[n]);
  std::vector<long> fill(e.start.begin(), e.start.end() - 1);
  each_pair([&](int later, int earlier) { e.index[fill[later]++] = earlier; });
  return e;
}

/// Liu's elimination tree with path compression: parent[k], or -1 for a root.
std::vector<int> elimination_tree(const EarlierNeighbours& e, int n) {
  std::vector<int> parent(n, -1), ancestor(n, -1);
  for (int k = 0; k < n; ++k) {
    for (long a = e.start[k]; a < e.start[k + 1]; ++a) {
      int j = e.index[a];
      while (j != -1 && j < k) {
        const int next = ancestor[j];
        ancestor[j] = k;
        if (next == -1)
          parent[j] = k;
        j = next;
      }
    }
  }
  return parent;
}

/// The tree's postorder: post[k] = the node visited k-th, children and roots in increasing order.
std::vector<int> postorder(const std::vector<int>& parent) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> first_child(n, -1), next_sibling(n, -1);
  for (int j = n - 1; j >= 0; --j) {  // pushed in decreasing order: lists increase
    if (parent[j] >= 0) {
      next_sibling[j] = first_child[parent[j]];
      first_child[parent[j]] = j;
    }
  }
  std::vector<int> post, stack;
  post.reserve(n);
  for (int root = 0; root < n; ++root) {
    if (parent[root] >= 0)
      continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int top = stack.back();
      const int child = first_child[top];
      if (child >= 0) {
        first_child[top] = next_sibling[child];  // consume the child, then descend
        stack.push_back(child);
      } else {
        post.push_back(top);
        stack.pop_back();
      }
    }
  }
  return post;
}

}  // namespace

std::vector<int> postordered_leading_block(const Eigen::SparseMatrix<double>& A_lower,
                                           const std::vector<int>& perm, int n_leading) {
  std::vector<int> position(A_lower.rows(), -1);
  for (int k = 0; k < n_leading; ++k)
    position[perm[k]] = k;
  const std::vector<int> post =
      postorder(elimination_tree(earlier_neighbours(A_lower, position, n_leading), n_leading));
  std::vector<int> out;
  out.reserve(perm.size());
  for (int k : post)
    out.push_back(perm[k]);
  out.insert(out.end(), perm.begin() + n_leading, perm.end());
  return out;
}

}  // namespace cs::solver

#include "solver/fill_reducing_ordering.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <metis.h>

#include "solver/per_thread_rand.hpp"

namespace cs::solver {

std::unique_lock<std::mutex> metis_turn() {
  static const bool per_thread = rand_is_per_thread();
  if (per_thread)
    return {};
  static std::mutex metis;
  return std::unique_lock(metis);
}

std::vector<int> metis_quotient_ordering(const Eigen::SparseMatrix<double>& A,
                                         const std::vector<int>& group_of_equation) {
  const int n = static_cast<int>(A.rows());
  if (static_cast<int>(group_of_equation.size()) != n) {
    throw std::invalid_argument("metis_quotient_ordering: one group per equation expected");
  }
  int n_groups = 0;
  for (int g : group_of_equation)
    n_groups = std::max(n_groups, g + 1);
  // Compact the group numbering (groups without equations are dropped).
  std::vector<int> compact(n_groups, -1);
  int n_vertices = 0;
  for (int g : group_of_equation) {
    if (compact[g] < 0)
      compact[g] = n_vertices++;
  }
  std::vector<int> vertex(n);
  for (int i = 0; i < n; ++i)
    vertex[i] = compact[group_of_equation[i]];

  // Equations of each vertex (CSR), in increasing order.
  std::vector<int> eq_start(n_vertices + 1, 0);
  for (int i = 0; i < n; ++i)
    ++eq_start[vertex[i] + 1];
  for (int v = 0; v < n_vertices; ++v)
    eq_start[v + 1] += eq_start[v];
  std::vector<int> eqs(n);
  {
    std::vector<int> fill(eq_start.begin(), eq_start.end() - 1);
    for (int i = 0; i < n; ++i)
      eqs[fill[vertex[i]]++] = i;
  }

  // Quotient graph edges from the lower triangle: each off-group entry gives (min, max) once
  // per vertex pair after deduplication; then symmetrize.
  std::vector<idx_t> up_start(n_vertices + 1, 0);
  std::vector<idx_t> up;
  {
    // Count with duplicates per lower vertex, fill, then sort-unique per vertex.
    std::vector<long> count(n_vertices + 1, 0);
    for (int j = 0; j < n; ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
        const int a = vertex[it.row()], b = vertex[j];
        if (a != b)
          ++count[std::min(a, b) + 1];
      }
    }
    for (int v = 0; v < n_vertices; ++v)
      count[v + 1] += count[v];
    std::vector<int> raw(count[n_vertices]);
    std::vector<long> fill(count.begin(), count.end() - 1);
    for (int j = 0; j < n; ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
        const int a = vertex[it.row()], b = vertex[j];
        if (a != b)
          raw[fill[std::min(a, b)]++] = std::max(a, b);
      }
    }
    for (int v = 0; v < n_vertices; ++v) {
      auto first = raw.begin() + count[v];
      auto last = raw.begin() + count[v + 1];
      std::sort(first, last);
      last = std::unique(first, last);
      up.insert(up.end(), first, last);
      up_start[v + 1] = static_cast<idx_t>(up.size());
    }
  }
  std::vector<idx_t> xadj(n_vertices + 1, 0);
  for (int v = 0; v < n_vertices; ++v) {
    for (idx_t k = up_start[v]; k < up_start[v + 1]; ++k) {
      ++xadj[v + 1];
      ++xadj[up[k] + 1];
    }
  }
  for (int v = 0; v < n_vertices; ++v)
    xadj[v + 1] += xadj[v];
  std::vector<idx_t> adjncy(xadj[n_vertices]);
  {
    std::vector<idx_t> fill(xadj.begin(), xadj.end() - 1);
    for (int v = 0; v < n_vertices; ++v) {
      for (idx_t k = up_start[v]; k < up_start[v + 1]; ++k) {
        adjncy[fill[v]++] = up[k];
        adjncy[fill[up[k]]++] = v;
      }
    }
  }
  up.clear();
  up.shrink_to_fit();

  std::vector<idx_t> perm(n_vertices), iperm(n_vertices);
  if (n_vertices > 0) {
    idx_t nv = n_vertices;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    const auto turn = metis_turn();
    const int status =
        METIS_NodeND(&nv, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data());
    if (status != METIS_OK) {
      throw std::runtime_error("METIS_NodeND failed with status " + std::to_string(status));
    }
  }
  std::vector<int> order;
  order.reserve(n);
  for (int k = 0; k < n_vertices; ++k) {
    const int v = static_cast<int>(perm[k]);
    for (int e = eq_start[v]; e < eq_start[v + 1]; ++e)
      order.push_back(eqs[e]);
  }
  return order;
}

}  // namespace cs::solver

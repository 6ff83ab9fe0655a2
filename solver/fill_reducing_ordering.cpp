#include "solver/fill_reducing_ordering.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <fmt/format.h>

#include <metis.h>

#include "solver/per_thread_rand.hpp"
#include "solver/spare_cores.hpp"

namespace cs::solver {

std::unique_lock<std::mutex> metis_turn() {
  static const bool per_thread = rand_is_per_thread();
  if (per_thread)
    return {};
  static std::mutex metis;
  return std::unique_lock(metis);
}

namespace {

/// An undirected graph in METIS's form: the neighbours of v are adjncy[xadj[v] .. xadj[v+1]).
struct Graph {
  std::vector<idx_t> xadj{0};
  std::vector<idx_t> adjncy;
  idx_t vertices() const { return static_cast<idx_t>(xadj.size()) - 1; }
};

void check_metis(int status, const char* call) {
  if (status != METIS_OK)
    throw std::runtime_error(fmt::format("{} failed with status {}", call, status));
}

/// METIS's default options, numbering from 0.
std::array<idx_t, METIS_NOPTIONS> default_options() {
  std::array<idx_t, METIS_NOPTIONS> options{};
  METIS_SetDefaultOptions(options.data());
  options[METIS_OPTION_NUMBERING] = 0;
  return options;
}

/// METIS's nested-dissection ordering of g: perm[k] = the vertex eliminated k-th.
std::vector<idx_t> metis_node_nd(Graph& g) {
  idx_t nv = g.vertices();
  std::vector<idx_t> perm(nv), iperm(nv);
  if (nv == 0)
    return perm;
  std::array<idx_t, METIS_NOPTIONS> options = default_options();
  const auto turn = metis_turn();
  check_metis(METIS_NodeND(&nv, g.xadj.data(), g.adjncy.data(), nullptr, options.data(),
                           perm.data(), iperm.data()),
              "METIS_NodeND");
  return perm;
}

/// The subgraph of g induced by the vertices v with part[v] == which; `vertices` receives its
/// vertices (subgraph index -> vertex of g).
Graph induced_subgraph(const Graph& g, const std::vector<idx_t>& part, idx_t which,
                       std::vector<idx_t>& vertices) {
  const idx_t n = g.vertices();
  std::vector<idx_t> index(n, -1);
  vertices.clear();
  for (idx_t v = 0; v < n; ++v) {
    if (part[v] == which) {
      index[v] = static_cast<idx_t>(vertices.size());
      vertices.push_back(v);
    }
  }
  Graph sub;
  sub.xadj.reserve(vertices.size() + 1);
  for (idx_t v : vertices) {
    for (idx_t k = g.xadj[v]; k < g.xadj[v + 1]; ++k) {
      if (index[g.adjncy[k]] >= 0)
        sub.adjncy.push_back(index[g.adjncy[k]]);
    }
    sub.xadj.push_back(static_cast<idx_t>(sub.adjncy.size()));
  }
  return sub;
}

/// METIS's vertex separator of g: part[v] = 0 or 1 for the two sides, 2 for the separator.
std::vector<idx_t> vertex_separator(Graph& g) {
  idx_t nv = g.vertices();
  idx_t separator_size = 0;
  std::vector<idx_t> part(nv);
  if (nv == 0)
    return part;
  std::array<idx_t, METIS_NOPTIONS> options = default_options();
  const auto turn = metis_turn();
  check_metis(METIS_ComputeVertexSeparator(&nv, g.xadj.data(), g.adjncy.data(), nullptr,
                                           options.data(), &separator_size, part.data()),
              "METIS_ComputeVertexSeparator");
  return part;
}

/// Nested dissection of g. From kSplitFrom vertices on, the first level is taken here: METIS's
/// vertex separator splits g into two parts, METIS orders each part on its own (at once when a
/// spare core is idle), and the separator is eliminated last, in vertex order. Each METIS call
/// reseeds its generator, so the permutation is the same on one thread or two.
std::vector<idx_t> nested_dissection(Graph g) {
  if (g.vertices() < kSplitFrom)
    return metis_node_nd(g);
  const idx_t nv = g.vertices();
  const std::vector<idx_t> part = vertex_separator(g);
  std::vector<idx_t> vertices0, vertices1;
  Graph g0 = induced_subgraph(g, part, 0, vertices0);
  Graph g1 = induced_subgraph(g, part, 1, vertices1);
  g = Graph{};
  std::vector<idx_t> perm0, perm1;
  run_both([&] { perm0 = metis_node_nd(g0); }, [&] { perm1 = metis_node_nd(g1); });
  std::vector<idx_t> perm;
  perm.reserve(nv);
  for (idx_t k : perm0)
    perm.push_back(vertices0[k]);
  for (idx_t k : perm1)
    perm.push_back(vertices1[k]);
  for (idx_t v = 0; v < nv; ++v) {
    if (part[v] == 2)
      perm.push_back(v);
  }
  return perm;
}

}  // namespace

namespace {

/// The graph whose vertices are the groups of equations (quotient_graph()).
struct QuotientGraph {
  Graph graph;
  std::vector<int> vertex;    ///< per equation: its vertex, -1 if left out
  std::vector<int> eq_start;  ///< the equations of vertex v: eqs[eq_start[v] .. eq_start[v+1])
  std::vector<int> eqs;
};

/// The quotient graph of A's pattern on the groups of `group_of_equation` (see
/// metis_quotient_ordering); `caller` names the entry point in the error for a wrong size.
QuotientGraph quotient_graph(const Eigen::SparseMatrix<double>& A,
                             const std::vector<int>& group_of_equation, const char* caller) {
  const int n = static_cast<int>(A.rows());
  if (static_cast<int>(group_of_equation.size()) != n) {
    throw std::invalid_argument(fmt::format("{}: one group per equation expected", caller));
  }
  int n_groups = 0;
  for (int g : group_of_equation)
    n_groups = std::max(n_groups, g + 1);
  // Compact the group numbering (groups without equations are dropped); the equations left out
  // (negative group) have no vertex.
  std::vector<int> compact(n_groups, -1);
  int n_vertices = 0;
  for (int g : group_of_equation) {
    if (g >= 0 && compact[g] < 0)
      compact[g] = n_vertices++;
  }
  std::vector<int> vertex(n, -1);
  int n_kept = 0;
  for (int i = 0; i < n; ++i) {
    if (group_of_equation[i] >= 0) {
      vertex[i] = compact[group_of_equation[i]];
      ++n_kept;
    }
  }

  // Equations of each vertex (CSR), in increasing order.
  std::vector<int> eq_start(n_vertices + 1, 0);
  for (int i = 0; i < n; ++i) {
    if (vertex[i] >= 0)
      ++eq_start[vertex[i] + 1];
  }
  for (int v = 0; v < n_vertices; ++v)
    eq_start[v + 1] += eq_start[v];
  std::vector<int> eqs(n_kept);
  {
    std::vector<int> fill(eq_start.begin(), eq_start.end() - 1);
    for (int i = 0; i < n; ++i) {
      if (vertex[i] >= 0)
        eqs[fill[vertex[i]]++] = i;
    }
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
        if (a != b && a >= 0 && b >= 0)
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
        if (a != b && a >= 0 && b >= 0)
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
  return {Graph{std::move(xadj), std::move(adjncy)}, std::move(vertex), std::move(eq_start),
          std::move(eqs)};
}

}  // namespace

std::vector<int> metis_quotient_ordering(const Eigen::SparseMatrix<double>& A,
                                         const std::vector<int>& group_of_equation) {
  QuotientGraph q = quotient_graph(A, group_of_equation, "metis_quotient_ordering");
  const std::vector<idx_t> perm = nested_dissection(std::move(q.graph));
  std::vector<int> order;
  order.reserve(q.eqs.size());
  for (idx_t v : perm) {
    for (int e = q.eq_start[v]; e < q.eq_start[v + 1]; ++e)
      order.push_back(q.eqs[e]);
  }
  return order;
}

std::vector<int> quotient_bisection(const Eigen::SparseMatrix<double>& A,
                                    const std::vector<int>& group_of_equation) {
  QuotientGraph q = quotient_graph(A, group_of_equation, "quotient_bisection");
  const std::vector<idx_t> part = vertex_separator(q.graph);
  std::vector<int> side(q.vertex.size(), -1);
  for (std::size_t eq = 0; eq < side.size(); ++eq) {
    if (q.vertex[eq] >= 0)
      side[eq] = static_cast<int>(part[q.vertex[eq]]);
  }
  return side;
}

}  // namespace cs::solver

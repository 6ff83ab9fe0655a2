#include "solver/assembly.hpp"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "solver/elements/element_stiffness.hpp"
#include "solver/model_error.hpp"
#include "solver/spare_cores.hpp"

namespace cs::solver {
namespace {

/// Elements whose matrices are computed at once before they are added: 2,048 of 16 x 16 take
/// 4 MiB.
constexpr int kElementsPerStep = 2048;

/// Node -> nodes sharing an element with it (including itself), CSR, sorted.
void node_adjacency(const Mesh& mesh, std::vector<int>& start, std::vector<int>& adjacent) {
  const int n_nodes = mesh.n_nodes();
  const int nen = mesh.n_element_nodes();
  // node -> elements
  std::vector<int> el_start(n_nodes + 1, 0);
  for (const auto& e : mesh.elements) {
    for (int a = 0; a < nen; ++a)
      ++el_start[e[a] + 1];
  }
  for (int n = 0; n < n_nodes; ++n)
    el_start[n + 1] += el_start[n];
  std::vector<int> el_of(el_start[n_nodes]);
  std::vector<int> fill(el_start.begin(), el_start.end() - 1);
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int a = 0; a < nen; ++a)
      el_of[fill[mesh.elements[e][a]]++] = e;
  }
  start.assign(n_nodes + 1, 0);
  adjacent.clear();
  adjacent.reserve(static_cast<std::size_t>(n_nodes) * (nen == 4 ? 9 : 17));
  std::vector<int> scratch;
  for (int n = 0; n < n_nodes; ++n) {
    scratch.clear();
    for (int k = el_start[n]; k < el_start[n + 1]; ++k) {
      const auto& e = mesh.elements[el_of[k]];
      scratch.insert(scratch.end(), e.begin(), e.begin() + nen);
    }
    if (scratch.empty())
      scratch.push_back(n);  // an orphan node couples to itself only
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    adjacent.insert(adjacent.end(), scratch.begin(), scratch.end());
    start[n + 1] = static_cast<int>(adjacent.size());
  }
}

}  // namespace

Assembler::Assembler(const Model& model, const DofMap& dofs) : model_(model), dofs_(dofs) {
  const Mesh& mesh = model.mesh;
  std::vector<int> adj_start;
  std::vector<int> adjacent;
  node_adjacency(mesh, adj_start, adjacent);

  // Column j (free DOF d = 2 n + c): rows = free DOFs of the neighbours m >= n with eq >= j.
  const int n_free = dofs.n_free();
  outer_.assign(n_free + 1, 0);
  inner_.clear();
  // At most 2 x 2 entries per pair of neighbours m >= n: reserved (untouched pages cost
  // nothing) so that growing never copies the pattern.
  inner_.reserve(2 * (adjacent.size() + static_cast<std::size_t>(mesh.n_nodes())));
  for (int j = 0; j < n_free; ++j) {
    const int d = dofs.free_dofs()[j];
    const int n = d / 2;
    for (int k = adj_start[n]; k < adj_start[n + 1]; ++k) {
      const int m = adjacent[k];
      if (m < n)
        continue;
      for (int c = 0; c < 2; ++c) {
        const int eq = dofs.equation(2 * m + c);
        if (eq >= j)
          inner_.push_back(eq);
      }
    }
    outer_[j + 1] = static_cast<int>(inner_.size());
  }

  // Scatter map: local lower-triangle pair (i >= j), column-major, -> position in inner_. The
  // halves of the elements on this core and, when one is idle, a borrowed one.
  const int nd = 2 * mesh.n_element_nodes();
  pairs_per_element_ = nd * (nd + 1) / 2;
  scatter_.assign(static_cast<std::size_t>(mesh.n_elements()) * pairs_per_element_, -1);
  const int half = mesh.n_elements() / 2;
  run_both([&] { map_elements(0, half); }, [&] { map_elements(half, mesh.n_elements()); });
}

void Assembler::map_elements(int first, int last) {
  const Mesh& mesh = model_.mesh;
  const int nd = 2 * mesh.n_element_nodes();
  int eq[16];
  for (int e = first; e < last; ++e) {
    for (int a = 0; a < nd / 2; ++a) {
      eq[2 * a] = dofs_.equation(2 * mesh.elements[e][a]);
      eq[2 * a + 1] = dofs_.equation(2 * mesh.elements[e][a] + 1);
    }
    int* out = scatter_.data() + static_cast<std::size_t>(e) * pairs_per_element_;
    for (int j = 0; j < nd; ++j) {
      for (int i = j; i < nd; ++i, ++out) {
        if (eq[i] < 0 || eq[j] < 0)
          continue;
        const int row = std::max(eq[i], eq[j]);
        const int col = std::min(eq[i], eq[j]);
        const int* begin = inner_.data() + outer_[col];
        const int* end = inner_.data() + outer_[col + 1];
        const int* pos = std::lower_bound(begin, end, row);
        *out = static_cast<int>(pos - inner_.data());
      }
    }
  }
}

void Assembler::add_element(int e, const ElementMatrix& K_e, double* values,
                            std::vector<Eigen::Triplet<double>>& constrained) const {
  const Mesh& mesh = model_.mesh;
  const int nd = 2 * mesh.n_element_nodes();
  const int* map = scatter_.data() + static_cast<std::size_t>(e) * pairs_per_element_;
  for (int j = 0; j < nd; ++j) {
    for (int i = j; i < nd; ++i, ++map) {
      if (*map >= 0)
        values[*map] += K_e(i, j);
    }
  }
  // Rows of prescribed DOFs, all columns.
  for (int i = 0; i < nd; ++i) {
    const int ci = dofs_.constrained_index(2 * mesh.elements[e][i / 2] + i % 2);
    if (ci < 0)
      continue;
    for (int j = 0; j < nd; ++j)
      constrained.emplace_back(ci, 2 * mesh.elements[e][j / 2] + j % 2, K_e(i, j));
  }
}

void Assembler::assemble(StiffnessMatrices& out) const {
  const Mesh& mesh = model_.mesh;
  const int n_free = dofs_.n_free();

  // K_ff: install the pattern (once), then zero the values.
  Eigen::SparseMatrix<double>& K = out.K_ff;
  const bool has_pattern =
      K.rows() == n_free && K.cols() == n_free && K.isCompressed() && K.nonZeros() == nnz() &&
      std::memcmp(K.outerIndexPtr(), outer_.data(), outer_.size() * sizeof(int)) == 0 &&
      std::memcmp(K.innerIndexPtr(), inner_.data(), inner_.size() * sizeof(int)) == 0;
  if (!has_pattern) {
    K.resize(n_free, n_free);
    K.resizeNonZeros(nnz());
    std::memcpy(K.outerIndexPtr(), outer_.data(), outer_.size() * sizeof(int));
    std::memcpy(K.innerIndexPtr(), inner_.data(), inner_.size() * sizeof(int));
  }
  double* values = K.valuePtr();
  std::fill(values, values + nnz(), 0.0);

  // Materials may have changed since validation (re-assembly after a value change).
  if (static_cast<int>(model_.materials.size()) != model_.n_bodies()) {
    throw ModelError(fmt::format("{} materials given for {} bodies", model_.materials.size(),
                                 model_.n_bodies()));
  }
  std::vector<Eigen::Matrix4d> D(model_.materials.size());
  for (std::size_t b = 0; b < D.size(); ++b) {
    validate(model_.materials[b], mesh.body_names[b]);
    D[b] = elasticity_matrix(model_.materials[b]);
  }

  const int points = model_.element_points();
  std::vector<Eigen::Triplet<double>> constrained;
  // A step's element matrices are computed in two halves, on this core and, when one is idle,
  // a borrowed one, then added in element order: the sums do not depend on where they ran.
  std::vector<ElementMatrix> K_step(std::min(kElementsPerStep, mesh.n_elements()));
  const auto compute = [&](int step_first, int first, int last) {
    for (int e = first; e < last; ++e) {
      element_stiffness(element_geometry(mesh, model_.analysis, e), D[mesh.element_body[e]], points,
                        K_step[e - step_first]);
    }
  };
  for (int step = 0; step < mesh.n_elements(); step += kElementsPerStep) {
    const int last = std::min(mesh.n_elements(), step + kElementsPerStep);
    const int mid = step + (last - step) / 2;
    run_both([&] { compute(step, step, mid); }, [&] { compute(step, mid, last); });
    for (int e = step; e < last; ++e)
      add_element(e, K_step[e - step], values, constrained);
  }
  out.K_cg.resize(dofs_.n_constrained(), dofs_.n_dofs());
  out.K_cg.setFromTriplets(constrained.begin(), constrained.end());
}

}  // namespace cs::solver

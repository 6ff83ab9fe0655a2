#include "solver/patch_recovery.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <utility>

#include <Eigen/QR>

namespace cs::solver {
namespace {

/// Up to 6 monomials, on the stack (evaluated for every node of every patch).
using Monomials = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
using Coefficients = Eigen::Matrix<double, Eigen::Dynamic, 4, 0, 6, 4>;
using NormalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;

/// The monomials of a complete polynomial of degree 1 or 2 at the scaled point p.
Monomials monomials(int degree, const Eigen::Vector2d& p) {
  Monomials m(degree == 1 ? 3 : 6);
  m[0] = 1.0;
  m[1] = p.x();
  m[2] = p.y();
  if (degree == 2) {
    m[3] = p.x() * p.x();
    m[4] = p.x() * p.y();
    m[5] = p.y() * p.y();
  }
  return m;
}

int n_monomials(int degree) {
  return (degree + 1) * (degree + 2) / 2;
}

}  // namespace

/// What PatchScope::Impl holds. Named, not file-local: a class with linkage holds them.
namespace patch_scope_parts {

/// The elements of one body around each node, in compressed rows: the elements around node n
/// are elements[offsets[n] .. offsets[n + 1]).
struct NodeElements {
  std::vector<int> offsets;
  std::vector<int> elements;
  std::span<const int> of(int node) const {
    return {elements.data() + offsets[node], elements.data() + offsets[node + 1]};
  }
};

/// The patches of one body that a recovery uses: its vertices' element lists, the patch centres
/// (increasing) and which vertices lie on the body's boundary.
struct BodyPatches {
  NodeElements around;
  std::vector<int> centres;
  std::vector<char> boundary;
};

}  // namespace patch_scope_parts

namespace {

using patch_scope_parts::BodyPatches;
using patch_scope_parts::NodeElements;

NodeElements elements_around(const Mesh& mesh, int body) {
  NodeElements around;
  around.offsets.assign(mesh.n_nodes() + 1, 0);
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_body[e] != body)
      continue;
    for (int a = 0; a < 4; ++a)
      ++around.offsets[mesh.elements[e][a] + 1];
  }
  for (int n = 0; n < mesh.n_nodes(); ++n)
    around.offsets[n + 1] += around.offsets[n];
  around.elements.resize(around.offsets.back());
  std::vector<int> next(around.offsets.begin(), around.offsets.end() - 1);
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_body[e] != body)
      continue;
    for (int a = 0; a < 4; ++a)
      around.elements[next[mesh.elements[e][a]]++] = e;
  }
  return around;
}

/// Whether each corner node marked in `vertices` lies on the boundary of one body: on a
/// corner-to-corner edge that only one element of the body has (0 for unmarked nodes). A local
/// test: the edges at a vertex are those of the body's elements around it.
std::vector<char> boundary_vertices(const Mesh& mesh, int body, const std::vector<char>& vertices) {
  std::vector<std::pair<int, int>> edges;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_body[e] != body)
      continue;
    for (int s = 0; s < 4; ++s) {
      const int a = mesh.elements[e][s], b = mesh.elements[e][(s + 1) % 4];
      if (vertices[a] || vertices[b])
        edges.push_back(std::minmax(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<char> boundary(mesh.n_nodes(), 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    if (j - i == 1) {
      boundary[edges[i].first] |= vertices[edges[i].first];
      boundary[edges[i].second] |= vertices[edges[i].second];
    }
    i = j;
  }
  return boundary;
}

/// A fitted patch polynomial: stress(x) = coefficients^T monomials((x - centre) / scale).
struct PatchFit {
  int degree = 1;
  Eigen::Vector2d centre;
  double scale = 1.0;
  Coefficients coefficients;

  Eigen::Vector4d at(const Eigen::Vector2d& x) const {
    return coefficients.transpose() * monomials(degree, (x - centre) / scale);
  }
};

/// Least-squares fit over the sampling points of `patch`; false if the points do not determine
/// the polynomial (too few, or on a line/conic).
bool fit_patch(const Mesh& mesh, const ElementSamples& samples, std::span<const int> patch,
               int node, int degree, PatchFit& fit) {
  fit.degree = degree;
  fit.centre = mesh.nodes[node];
  int m = 0;
  fit.scale = 0.0;
  for (int e : patch) {
    for (const StressSample& s : samples[e]) {
      fit.scale = std::max(fit.scale, (s.position - fit.centre).norm());
      ++m;
    }
  }
  const int k = n_monomials(degree);
  if (m < k || fit.scale <= 0.0)
    return false;
  // Normal equations on points scaled into the unit disc: well conditioned, no heap.
  NormalMatrix AtA = NormalMatrix::Zero(k, k);
  Coefficients Atb = Coefficients::Zero(k, 4);
  for (int e : patch) {
    for (const StressSample& s : samples[e]) {
      const Monomials a = monomials(degree, (s.position - fit.centre) / fit.scale);
      AtA.noalias() += a * a.transpose();
      Atb.noalias() += a * s.stress.transpose();
    }
  }
  Eigen::ColPivHouseholderQR<NormalMatrix> qr(AtA);
  qr.setThreshold(1e-10);
  if (qr.rank() < k)
    return false;
  fit.coefficients = qr.solve(Atb);
  return true;
}

}  // namespace

int patch_polynomial_degree(ElementType type) {
  return type == ElementType::Q4 ? 1 : 2;
}

const std::vector<Eigen::Vector2d>& patch_sampling_points(ElementType type) {
  static const std::vector<Eigen::Vector2d> centre{Eigen::Vector2d::Zero()};
  static const std::vector<Eigen::Vector2d> barlow = [] {
    const double g = 1.0 / std::sqrt(3.0);
    return std::vector<Eigen::Vector2d>{{-g, -g}, {g, -g}, {g, g}, {-g, g}};
  }();
  return type == ElementType::Q4 ? centre : barlow;
}

namespace {

/// The vertices whose patches reach a node of `nodes` (nullptr: every node) in `body`, as a
/// mask: the corners of the body's elements that hold such a node.
std::vector<char> patch_centres(const Mesh& mesh, int body, const std::vector<char>* nodes) {
  std::vector<char> centre(mesh.n_nodes(), 0);
  const int nen = mesh.n_element_nodes();
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_body[e] != body)
      continue;
    bool reaches = nodes == nullptr;
    for (int a = 0; a < nen && !reaches; ++a)
      reaches = (*nodes)[mesh.elements[e][a]] != 0;
    if (!reaches)
      continue;
    for (int a = 0; a < 4; ++a)
      centre[mesh.elements[e][a]] = 1;
  }
  return centre;
}

BodyPatches body_patches(const Mesh& mesh, int body, const std::vector<char>* nodes) {
  BodyPatches b;
  b.around = elements_around(mesh, body);
  const std::vector<char> centre = patch_centres(mesh, body, nodes);
  b.boundary = boundary_vertices(mesh, body, centre);
  for (int node = 0; node < mesh.n_nodes(); ++node) {
    if (centre[node] && !b.around.of(node).empty())
      b.centres.push_back(node);
  }
  return b;
}

/// The patch recovery of one body at the nodes of `nodes` (nullptr: every node), from the
/// patches of `b.centres` in increasing node order (so that a node's sum over patches adds in
/// the same order whatever `nodes` is).
void recover_body(const Mesh& mesh, const ElementSamples& samples, const BodyPatches& b,
                  const std::vector<char>* nodes, std::vector<Eigen::Vector4d>& nodal,
                  std::vector<int>& count) {
  const int degree = patch_polynomial_degree(mesh.type);
  const int nen = mesh.n_element_nodes();
  auto wanted = [&](int node) { return nodes == nullptr || (*nodes)[node] != 0; };
  // Interior vertices: their own patch. Others: sum of the patches reaching them.
  std::vector<char> own(mesh.n_nodes(), 0);
  std::vector<Eigen::Vector4d> sum(mesh.n_nodes(), Eigen::Vector4d::Zero());
  std::vector<int> reached(mesh.n_nodes(), 0);
  PatchFit fit;
  for (int node : b.centres) {
    const std::span<const int> patch = b.around.of(node);
    if (b.boundary[node] || !fit_patch(mesh, samples, patch, node, degree, fit))
      continue;
    if (wanted(node)) {
      nodal[node] = fit.at(mesh.nodes[node]);
      count[node] = 1;
    }
    own[node] = 1;
    for (int e : patch) {
      for (int a = 0; a < nen; ++a) {
        const int other = mesh.elements[e][a];
        const bool interior_vertex = a < 4 && !b.boundary[other];
        if (other == node || interior_vertex || !wanted(other))
          continue;
        sum[other] += fit.at(mesh.nodes[other]);
        ++reached[other];
      }
    }
  }
  for (int node = 0; node < mesh.n_nodes(); ++node) {
    if (own[node] || reached[node] == 0 || !wanted(node))
      continue;
    nodal[node] = sum[node] / reached[node];
    count[node] = reached[node];
  }
}

}  // namespace

struct PatchScope::Impl {
  std::vector<char> nodes;
  std::vector<char> elements;
  std::vector<BodyPatches> bodies;
};

PatchScope::PatchScope(const Mesh& mesh, int n_bodies, std::vector<char> nodes) {
  auto impl = std::make_shared<Impl>();
  impl->nodes = std::move(nodes);
  impl->elements.assign(mesh.n_elements(), 0);
  for (int body = 0; body < n_bodies; ++body) {
    impl->bodies.push_back(body_patches(mesh, body, &impl->nodes));
    const BodyPatches& b = impl->bodies.back();
    for (int node : b.centres) {
      for (int e : b.around.of(node))
        impl->elements[e] = 1;
    }
  }
  impl_ = std::move(impl);
}

const std::vector<char>& PatchScope::nodes() const {
  return impl_->nodes;
}

const std::vector<char>& PatchScope::elements() const {
  return impl_->elements;
}

void recover_by_patches(const Mesh& mesh, const ElementSamples& samples,
                        std::vector<std::vector<Eigen::Vector4d>>& nodal,
                        std::vector<std::vector<int>>& count) {
  for (int body = 0; body < static_cast<int>(nodal.size()); ++body) {
    recover_body(mesh, samples, body_patches(mesh, body, nullptr), nullptr, nodal[body],
                 count[body]);
  }
}

void recover_by_patches(const Mesh& mesh, const ElementSamples& samples, const PatchScope& scope,
                        std::vector<std::vector<Eigen::Vector4d>>& nodal,
                        std::vector<std::vector<int>>& count) {
  const auto& bodies = scope.impl_->bodies;
  for (int body = 0; body < static_cast<int>(nodal.size()); ++body) {
    recover_body(mesh, samples, bodies.at(body), &scope.nodes(), nodal[body], count[body]);
  }
}

}  // namespace cs::solver

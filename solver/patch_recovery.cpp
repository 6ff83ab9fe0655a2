#include "solver/patch_recovery.hpp"

#include <algorithm>
#include <cmath>
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

/// The elements of one body around each node, in compressed rows: the elements around node n
/// are elements[offsets[n] .. offsets[n + 1]).
struct NodeElements {
  std::vector<int> offsets;
  std::vector<int> elements;
  std::span<const int> of(int node) const {
    return {elements.data() + offsets[node], elements.data() + offsets[node + 1]};
  }
};

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

/// Whether each corner node lies on the boundary of one body: on a corner-to-corner edge that
/// only one element of the body has.
std::vector<char> boundary_vertices(const Mesh& mesh, int body) {
  std::vector<std::pair<int, int>> edges;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_body[e] != body)
      continue;
    for (int s = 0; s < 4; ++s)
      edges.push_back(std::minmax(mesh.elements[e][s], mesh.elements[e][(s + 1) % 4]));
  }
  std::sort(edges.begin(), edges.end());
  std::vector<char> boundary(mesh.n_nodes(), 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    if (j - i == 1)
      boundary[edges[i].first] = boundary[edges[i].second] = 1;
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

void recover_by_patches(const Mesh& mesh, const ElementSamples& samples,
                        std::vector<std::vector<Eigen::Vector4d>>& nodal,
                        std::vector<std::vector<int>>& count) {
  const int n_bodies = static_cast<int>(nodal.size());
  const int degree = patch_polynomial_degree(mesh.type);
  const int nen = mesh.n_element_nodes();

  for (int body = 0; body < n_bodies; ++body) {
    const NodeElements around = elements_around(mesh, body);
    const std::vector<char> boundary = boundary_vertices(mesh, body);
    // Interior vertices: their own patch. Others: sum of the patches reaching them.
    std::vector<char> own(mesh.n_nodes(), 0);
    std::vector<Eigen::Vector4d> sum(mesh.n_nodes(), Eigen::Vector4d::Zero());
    std::vector<int> reached(mesh.n_nodes(), 0);
    PatchFit fit;
    for (int node = 0; node < mesh.n_nodes(); ++node) {
      const std::span<const int> patch = around.of(node);
      if (patch.empty() || boundary[node] || !fit_patch(mesh, samples, patch, node, degree, fit)) {
        continue;
      }
      nodal[body][node] = fit.at(mesh.nodes[node]);
      count[body][node] = 1;
      own[node] = 1;
      for (int e : patch) {
        for (int a = 0; a < nen; ++a) {
          const int other = mesh.elements[e][a];
          const bool interior_vertex = a < 4 && !boundary[other];
          if (other == node || interior_vertex)
            continue;
          sum[other] += fit.at(mesh.nodes[other]);
          ++reached[other];
        }
      }
    }
    for (int node = 0; node < mesh.n_nodes(); ++node) {
      if (own[node] || reached[node] == 0)
        continue;
      nodal[body][node] = sum[node] / reached[node];
      count[body][node] = reached[node];
    }
  }
}

}  // namespace cs::solver

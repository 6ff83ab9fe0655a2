#include "solver/patch_recovery.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <Eigen/QR>

namespace cs::solver {
namespace {

/// The monomials of a complete polynomial of degree 1 or 2 at the scaled point p.
Eigen::VectorXd monomials(int degree, const Eigen::Vector2d& p) {
  if (degree == 1)
    return Eigen::Vector3d(1.0, p.x(), p.y());
  Eigen::VectorXd m(6);
  m << 1.0, p.x(), p.y(), p.x() * p.x(), p.x() * p.y(), p.y() * p.y();
  return m;
}

int n_monomials(int degree) {
  return (degree + 1) * (degree + 2) / 2;
}

/// The elements of each body around each node: around[body][node].
std::vector<std::vector<std::vector<int>>> elements_around(const Mesh& mesh, int n_bodies) {
  std::vector<std::vector<std::vector<int>>> around(n_bodies,
                                                    std::vector<std::vector<int>>(mesh.n_nodes()));
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int a = 0; a < 4; ++a)
      around[mesh.element_body[e]][mesh.elements[e][a]].push_back(e);
  }
  return around;
}

/// Whether each corner node lies on the boundary of each body: on a corner-to-corner edge that
/// only one element of the body has. boundary[body][node].
std::vector<std::vector<char>> boundary_vertices(const Mesh& mesh, int n_bodies) {
  std::vector<std::map<std::pair<int, int>, int>> edge_count(n_bodies);
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int s = 0; s < 4; ++s) {
      const int a = mesh.elements[e][s], b = mesh.elements[e][(s + 1) % 4];
      ++edge_count[mesh.element_body[e]][std::minmax(a, b)];
    }
  }
  std::vector<std::vector<char>> boundary(n_bodies, std::vector<char>(mesh.n_nodes(), 0));
  for (int body = 0; body < n_bodies; ++body) {
    for (const auto& [edge, count] : edge_count[body]) {
      if (count == 1)
        boundary[body][edge.first] = boundary[body][edge.second] = 1;
    }
  }
  return boundary;
}

/// A fitted patch polynomial: stress(x) = coefficients^T monomials((x - centre) / scale).
struct PatchFit {
  int degree = 1;
  Eigen::Vector2d centre;
  double scale = 1.0;
  Eigen::Matrix<double, Eigen::Dynamic, 4> coefficients;

  Eigen::Vector4d at(const Eigen::Vector2d& x) const {
    return coefficients.transpose() * monomials(degree, (x - centre) / scale);
  }
};

/// Least-squares fit over the sampling points of `patch`; false if the points do not determine
/// the polynomial (too few, or on a line/conic).
bool fit_patch(const Mesh& mesh, const ElementSamples& samples, const std::vector<int>& patch,
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
  Eigen::MatrixXd A(m, k);
  Eigen::Matrix<double, Eigen::Dynamic, 4> b(m, 4);
  int row = 0;
  for (int e : patch) {
    for (const StressSample& s : samples[e]) {
      A.row(row) = monomials(degree, (s.position - fit.centre) / fit.scale).transpose();
      b.row(row) = s.stress.transpose();
      ++row;
    }
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  qr.setThreshold(1e-8);
  if (qr.rank() < k)
    return false;
  fit.coefficients = qr.solve(b);
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
  const auto around = elements_around(mesh, n_bodies);
  const auto boundary = boundary_vertices(mesh, n_bodies);

  for (int body = 0; body < n_bodies; ++body) {
    // Interior vertices: their own patch. Others: sum of the patches reaching them.
    std::vector<char> own(mesh.n_nodes(), 0);
    std::vector<Eigen::Vector4d> sum(mesh.n_nodes(), Eigen::Vector4d::Zero());
    std::vector<int> reached(mesh.n_nodes(), 0);
    PatchFit fit;
    for (int node = 0; node < mesh.n_nodes(); ++node) {
      const std::vector<int>& patch = around[body][node];
      if (patch.empty() || boundary[body][node] ||
          !fit_patch(mesh, samples, patch, node, degree, fit)) {
        continue;
      }
      nodal[body][node] = fit.at(mesh.nodes[node]);
      count[body][node] = 1;
      own[node] = 1;
      for (int e : patch) {
        for (int a = 0; a < nen; ++a) {
          const int other = mesh.elements[e][a];
          const bool interior_vertex = a < 4 && !boundary[body][other];
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

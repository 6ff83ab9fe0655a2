#include "solver/mesh/mesh_quality.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <Eigen/LU>

#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {
namespace {

// Reference corners of the counter-clockwise node order, then mid-side nodes 4..7.
constexpr std::array<double, 8> kXi = {-1, 1, 1, -1, 0, 1, 0, -1};
constexpr std::array<double, 8> kEta = {-1, -1, 1, 1, -1, 0, 1, 0};

/// Shape-function derivatives (d/dxi, d/deta) of node a at (xi, eta).
Eigen::Vector2d shape_gradient(ElementType type, int a, double xi, double eta) {
  const double xa = kXi[a];
  const double ea = kEta[a];
  if (type == ElementType::Q4) {
    return {0.25 * xa * (1 + ea * eta), 0.25 * ea * (1 + xa * xi)};
  }
  if (a < 4) {  // serendipity corner: N = (1+xa xi)(1+ea eta)(xa xi + ea eta - 1)/4
    return {0.25 * xa * (1 + ea * eta) * (2 * xa * xi + ea * eta),
            0.25 * ea * (1 + xa * xi) * (xa * xi + 2 * ea * eta)};
  }
  if (xa == 0) {  // mid-side on eta = ea: N = (1 - xi^2)(1 + ea eta)/2
    return {-xi * (1 + ea * eta), 0.5 * ea * (1 - xi * xi)};
  }
  return {0.5 * xa * (1 - eta * eta), -eta * (1 + xa * xi)};  // mid-side on xi = xa
}

double jacobian_determinant(const Mesh& mesh, int element, double xi, double eta) {
  Eigen::Matrix2d j = Eigen::Matrix2d::Zero();
  const auto& e = mesh.elements[element];
  for (int a = 0; a < mesh.n_element_nodes(); ++a) {
    const Eigen::Vector2d g = shape_gradient(mesh.type, a, xi, eta);
    j += mesh.nodes[e[a]] * g.transpose();  // column 0: d/dxi, column 1: d/deta
  }
  return j.determinant();
}

std::vector<double> gauss_abscissae(ElementType type) {
  if (type == ElementType::Q4) {
    const double g = 1.0 / std::sqrt(3.0);
    return {-g, g};
  }
  const double g = std::sqrt(0.6);
  return {-g, 0.0, g};
}

std::vector<double> gauss_weights(ElementType type) {
  if (type == ElementType::Q4) {
    return {1.0, 1.0};
  }
  return {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
}

}  // namespace

double min_jacobian_determinant(const Mesh& mesh, int element) {
  double least = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 4; ++c) {
    least = std::min(least, jacobian_determinant(mesh, element, kXi[c], kEta[c]));
  }
  const auto g = gauss_abscissae(mesh.type);
  for (double xi : g) {
    for (double eta : g) {
      least = std::min(least, jacobian_determinant(mesh, element, xi, eta));
    }
  }
  return least;
}

double min_jacobian_determinant(const Mesh& mesh) {
  double least = std::numeric_limits<double>::infinity();
  for (int e = 0; e < mesh.n_elements(); ++e) {
    least = std::min(least, min_jacobian_determinant(mesh, e));
  }
  return least;
}

void check_mesh(const Mesh& mesh) {
  if (mesh.element_body.size() != mesh.elements.size()) {
    throw MeshError(fmt::format("check_mesh: {} body indices for {} elements",
                                mesh.element_body.size(), mesh.elements.size()));
  }
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int a = 0; a < mesh.n_element_nodes(); ++a) {
      const int n = mesh.elements[e][a];
      if (n < 0 || n >= mesh.n_nodes()) {
        throw MeshError(fmt::format("check_mesh: element {} node {} is {} (mesh has {} nodes)", e,
                                    a, n, mesh.n_nodes()));
      }
    }
    const int body = mesh.element_body[e];
    if (body < 0 || body >= static_cast<int>(mesh.body_names.size())) {
      throw MeshError(fmt::format("check_mesh: element {} has body index {} ({} bodies)", e, body,
                                  mesh.body_names.size()));
    }
    const double det = min_jacobian_determinant(mesh, e);
    if (!(det > 0.0)) {
      throw MeshError(
          fmt::format("check_mesh: element {} is degenerate or inverted (min det J = {})", e, det));
    }
  }
}

MeshTopology mesh_topology(const Mesh& mesh) {
  // key: (lower corner, higher corner) -> number of uses, direction of the first use
  std::map<std::pair<int, int>, std::pair<int, bool>> uses;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int s = 0; s < 4; ++s) {
      const int a = mesh.elements[e][s];
      const int b = mesh.elements[e][(s + 1) % 4];
      auto& [count, forward] = uses[{std::min(a, b), std::max(a, b)}];
      if (count == 1 && forward == (a < b)) {
        throw MeshError(fmt::format(
            "mesh_topology: side {}-{} is traversed twice in the same direction (element {})", a, b,
            e));
      }
      if (count == 2) {
        throw MeshError(
            fmt::format("mesh_topology: side {}-{} belongs to more than two elements", a, b));
      }
      forward = a < b;
      ++count;
    }
  }
  MeshTopology topology;
  for (const auto& [key, use] : uses) {
    if (use.first == 2) {
      ++topology.n_interior_sides;
    } else {
      ++topology.n_boundary_sides;
      topology.boundary_length += (mesh.nodes[key.first] - mesh.nodes[key.second]).norm();
    }
  }
  return topology;
}

double element_area(const Mesh& mesh, int element) {
  const auto g = gauss_abscissae(mesh.type);
  const auto w = gauss_weights(mesh.type);
  double area = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    for (std::size_t k = 0; k < g.size(); ++k) {
      area += w[i] * w[k] * jacobian_determinant(mesh, element, g[i], g[k]);
    }
  }
  return area;
}

double element_size(const Mesh& mesh, int element) {
  return std::sqrt(std::abs(element_area(mesh, element)));
}

}  // namespace cs::solver

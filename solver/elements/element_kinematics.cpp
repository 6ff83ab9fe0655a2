#include "solver/elements/element_kinematics.hpp"

#include <fmt/format.h>
#include <Eigen/LU>

#include "solver/model_error.hpp"

namespace cs::solver {

ElementGeometry element_geometry(const Mesh& mesh, AnalysisType analysis, int element) {
  ElementGeometry g;
  g.type = mesh.type;
  g.analysis = analysis;
  g.n_nodes = mesh.n_element_nodes();
  const auto& conn = mesh.elements[element];
  for (int a = 0; a < g.n_nodes; ++a)
    g.x[a] = mesh.nodes[conn[a]];
  g.element = element;
  const int body =
      element < static_cast<int>(mesh.element_body.size()) ? mesh.element_body[element] : -1;
  if (body >= 0 && body < static_cast<int>(mesh.body_names.size())) {
    g.body_name = mesh.body_names[body];
  }
  return g;
}

Eigen::Vector2d natural_to_physical(const ElementGeometry& g, const Eigen::Vector2d& xi) {
  const ShapeValues s = shape_functions(g.type, xi);
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  for (int a = 0; a < g.n_nodes; ++a)
    x += s.N(a) * g.x[a];
  return x;
}

PointKinematics point_kinematics(const ElementGeometry& g, const Eigen::Vector2d& xi) {
  PointKinematics k;
  k.shape = shape_functions(g.type, xi);
  const int n = g.n_nodes;
  // J = [dx/dxi dx/deta; dz/dxi dz/deta]
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  k.position.setZero();
  for (int a = 0; a < n; ++a) {
    k.position += k.shape.N(a) * g.x[a];
    J.col(0) += k.shape.dN_dxi(a, 0) * g.x[a];
    J.col(1) += k.shape.dN_dxi(a, 1) * g.x[a];
  }
  k.det_j = J.determinant();
  if (!(k.det_j > 0.0)) {
    throw ModelError(fmt::format(
        "element {} of body '{}': det J = {:.6g} <= 0 at natural point ({:.4g}, {:.4g}) "
        "(inverted, degenerate or badly distorted element; nodes must run counter-clockwise)",
        g.element, g.body_name, k.det_j, xi.x(), xi.y()));
  }
  const bool axi = g.analysis == AnalysisType::Axisymmetric;
  k.radius = axi ? k.position.x() : 1.0;
  if (axi && !(k.radius > 0.0)) {
    throw ModelError(fmt::format(
        "element {} of body '{}': Gauss point at r = {:.6g} <= 0 (an axisymmetric mesh must "
        "lie in r >= 0)",
        g.element, g.body_name, k.radius));
  }
  // dN/dx = dN/dxi J^{-1}
  const Eigen::Matrix2d J_inv = J.inverse();
  k.dN_dx.setZero();
  k.dN_dx.topRows(n) = k.shape.dN_dxi.topRows(n) * J_inv;
  k.B.setZero(4, 2 * n);
  for (int a = 0; a < n; ++a) {
    const double dx = k.dN_dx(a, 0);
    const double dz = k.dN_dx(a, 1);
    k.B(0, 2 * a) = dx;
    k.B(1, 2 * a + 1) = dz;
    k.B(2, 2 * a) = dz;
    k.B(2, 2 * a + 1) = dx;
    if (axi)
      k.B(3, 2 * a) = k.shape.N(a) / k.radius;
  }
  return k;
}

}  // namespace cs::solver

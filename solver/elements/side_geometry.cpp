#include "solver/elements/side_geometry.hpp"

namespace cs::solver {

SidePoint side_point(const Mesh& mesh, const ElementSide& side, double t) {
  SidePoint p;
  p.nodes = mesh.side_nodes(side);
  p.shape = side_shape_functions(mesh.type, t);
  p.position.setZero();
  p.tangent.setZero();
  for (int k = 0; k < p.shape.n; ++k) {
    const Eigen::Vector2d& x = mesh.nodes[p.nodes[k]];
    p.position += p.shape.N[k] * x;
    p.tangent += p.shape.dN[k] * x;
  }
  p.jacobian = p.tangent.norm();
  p.outward_normal = Eigen::Vector2d(p.tangent.y(), -p.tangent.x()) / p.jacobian;
  return p;
}

}  // namespace cs::solver

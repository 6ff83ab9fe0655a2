#pragma once
// Geometry of one element side at a side coordinate: the surface description that edge loads,
// surface stresses and contact share.
//
// A side s of an element runs from corner s to corner (s+1)%4, with side coordinate t in
// [-1, 1] (see shape_functions.hpp). With the counter-clockwise node order of mesh.hpp the
// element lies to the left of the side's direction, so the outward normal is the tangent
// turned clockwise: n = (t_z, -t_x) / |t|.

#include <array>

#include <Eigen/Core>

#include "solver/elements/shape_functions.hpp"
#include "solver/mesh/mesh.hpp"

namespace cs::solver {

/// A point on an element side.
struct SidePoint {
  Eigen::Vector2d position;        ///< x(t)
  Eigen::Vector2d tangent;         ///< dx/dt (not normalized; points along the side direction)
  double jacobian = 0.0;           ///< |dx/dt|: ds = jacobian dt
  Eigen::Vector2d outward_normal;  ///< unit outward normal of the element
  SideShapeValues shape;           ///< side shape functions, in Mesh::side_nodes order
  std::array<int, 3> nodes{};      ///< Mesh::side_nodes (the third is -1 for Q4)
};

/// The point of side `side` at side coordinate t in [-1, 1].
SidePoint side_point(const Mesh& mesh, const ElementSide& side, double t);

}  // namespace cs::solver

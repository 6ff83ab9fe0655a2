#pragma once
// Shape functions of the Q4 (bilinear) and Q8 (serendipity) quadrilaterals and of their sides.
//
// Natural coordinates (xi, eta) in [-1, 1]^2. Node order as in solver/mesh/mesh.hpp:
// corners 0 (-1,-1), 1 (1,-1), 2 (1,1), 3 (-1,1); Q8 mid-side nodes 4 (0,-1), 5 (1,0),
// 6 (0,1), 7 (-1,0).
//   Q4 corner a:  N_a = (1 + xi xi_a)(1 + eta eta_a) / 4
//   Q8 corner a:  N_a = (1 + xi xi_a)(1 + eta eta_a)(xi xi_a + eta eta_a - 1) / 4
//   Q8 mid-side with xi_a = 0:   N_a = (1 - xi^2)(1 + eta eta_a) / 2
//   Q8 mid-side with eta_a = 0:  N_a = (1 + xi xi_a)(1 - eta^2) / 2
//
// A side s (0..3) runs from corner s to corner (s+1)%4 with the side coordinate t in [-1, 1]
// (t = -1 at corner s). Its nodes are ordered as Mesh::side_nodes returns them: corner s,
// corner s+1, and for Q8 the mid-side node. Side shape functions: linear (1-t)/2, (1+t)/2;
// quadratic t(t-1)/2, t(t+1)/2, 1-t^2.

#include <array>

#include <Eigen/Core>

#include "solver/mesh/mesh.hpp"

namespace cs::solver {

inline constexpr int kMaxElementNodes = 8;

/// Shape function values and their natural derivatives at one point; rows beyond n unused.
struct ShapeValues {
  int n = 0;                                          ///< number of nodes (4 or 8)
  Eigen::Matrix<double, kMaxElementNodes, 1> N;       ///< N_a
  Eigen::Matrix<double, kMaxElementNodes, 2> dN_dxi;  ///< (dN_a/dxi, dN_a/deta)
};

/// The shape functions of an element of type `type` at natural point `xi` = (xi, eta).
ShapeValues shape_functions(ElementType type, const Eigen::Vector2d& xi);

/// Natural coordinates of local node `a` (0..n-1) of an element of type `type`.
Eigen::Vector2d node_natural_coordinates(ElementType type, int a);

/// Natural coordinates (xi, eta) of the point with side coordinate t on local side `side`.
Eigen::Vector2d side_point_natural_coordinates(int side, double t);

/// Side shape functions at side coordinate t, in Mesh::side_nodes order; entries beyond n unused.
struct SideShapeValues {
  int n = 0;                   ///< nodes on the side (2 or 3)
  std::array<double, 3> N{};   ///< N_k(t)
  std::array<double, 3> dN{};  ///< dN_k/dt
};

/// The shape functions of a side of an element of type `type` at side coordinate t.
SideShapeValues side_shape_functions(ElementType type, double t);

}  // namespace cs::solver

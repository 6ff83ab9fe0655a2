#pragma once
// Consistent nodal forces of tractions and pressures on the sides of an edge set:
//   f_k += int_side N_k(t) traction(x(t)) w(x) |dx/dt| dt,  w = r (axisymmetric, per radian) | 1,
// by Gauss quadrature along each side (EdgeTraction::gauss_points, default 5 points: exact for
// the quadratic Q8 side shape functions times a polynomial traction up to degree 5 on straight
// sides, and accurate for smooth non-polynomial tractions).

#include <Eigen/Core>

#include "solver/model.hpp"

namespace cs::solver {

/// Adds the nodal forces of `traction` to the global force vector f (size 2 n_nodes).
void add_edge_traction(const Model& model, const EdgeTraction& traction, Eigen::VectorXd& f);

/// Adds the nodal forces of `pressure` (traction -p n, n the outward unit normal) to f.
void add_edge_pressure(const Model& model, const EdgePressure& pressure, Eigen::VectorXd& f);

}  // namespace cs::solver

#pragma once
// Element matrices and vectors of the displacement formulation of linear elasticity:
//   K_e = int_e B^T D B dV,   f_e = int_e N^T b dV,
// with dV = det J dxi deta (plane strain, per unit thickness) or det J r dxi deta
// (axisymmetric, per radian; see solver/analysis_type.hpp), by n x n Gauss quadrature.

#include <Eigen/Core>

#include "solver/elements/element_kinematics.hpp"
#include "solver/fields.hpp"

namespace cs::solver {

/// Gauss points per direction of full integration: 2 for Q4, 3 for Q8.
constexpr int default_gauss_points(ElementType type) {
  return type == ElementType::Q4 ? 2 : 3;
}

/// The element stiffness matrix (2n x 2n, symmetric) with `gauss_points` per direction.
/// Throws ModelError (naming the element and body) if det J <= 0 at a Gauss point.
void element_stiffness(const ElementGeometry& geometry, const Eigen::Matrix4d& D, int gauss_points,
                       ElementMatrix& K_e);

/// The consistent nodal forces of the body force b (force per unit volume) on the element.
void element_body_force(const ElementGeometry& geometry, const VectorField& b, int gauss_points,
                        ElementVector& f_e);

/// The stress D B u_e at natural point `xi` (components as in solver/material.hpp) for the
/// element displacement vector `u_e` (2n). `xi` must be an interior point.
Eigen::Vector4d element_stress_at(const ElementGeometry& geometry, const Eigen::Matrix4d& D,
                                  const ElementVector& u_e, const Eigen::Vector2d& xi);

}  // namespace cs::solver

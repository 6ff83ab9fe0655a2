#pragma once
// Geometry and kinematics of one quadrilateral element at a point: position, Jacobian, the
// radial weight of axisymmetric integrals, and the strain-displacement matrix B.
//
// The strain vector is (eps_x|r, eps_z, gamma_xz|rz, eps_y|theta) (see solver/material.hpp);
// element DOFs are ordered (u_x, u_z) of local node 0, then of node 1, ... (2 a + c).
// For node a, column 2a:   (dN_a/dx, 0, dN_a/dz, N_a/r [axisymmetric] | 0 [plane strain])
//             column 2a+1: (0, dN_a/dz, dN_a/dx, 0).

#include <array>
#include <string_view>

#include <Eigen/Core>

#include "solver/analysis_type.hpp"
#include "solver/elements/shape_functions.hpp"
#include "solver/mesh/mesh.hpp"

namespace cs::solver {

inline constexpr int kMaxElementDofs = 2 * kMaxElementNodes;

/// An element matrix (2n x 2n, n = 4 or 8), stack-allocated.
using ElementMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                    kMaxElementDofs, kMaxElementDofs>;
/// An element vector (2n), stack-allocated.
using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxElementDofs, 1>;
/// The strain-displacement matrix B (4 x 2n), stack-allocated.
using StrainDisplacementMatrix =
    Eigen::Matrix<double, 4, Eigen::Dynamic, Eigen::ColMajor, 4, kMaxElementDofs>;

/// The geometry of one element: what its matrices are computed from. `element` and
/// `body_name` only serve the error messages.
struct ElementGeometry {
  ElementType type = ElementType::Q4;
  AnalysisType analysis = AnalysisType::PlaneStrain;
  int n_nodes = 4;
  std::array<Eigen::Vector2d, kMaxElementNodes> x{};  ///< node coordinates (x|r, z)
  int element = -1;                                   ///< element index in its mesh
  std::string_view body_name;                         ///< name of the element's body
};

/// The geometry of element `element` of `mesh`.
ElementGeometry element_geometry(const Mesh& mesh, AnalysisType analysis, int element);

/// Kinematics at one natural point of an element.
struct PointKinematics {
  Eigen::Vector2d position;  ///< x(xi): (x|r, z)
  double det_j = 0.0;        ///< det(d(x, z) / d(xi, eta)) > 0
  double radius = 1.0;       ///< r at the point (axisymmetric) or 1 (plane strain)
  ShapeValues shape;         ///< N_a and natural derivatives
  Eigen::Matrix<double, kMaxElementNodes, 2> dN_dx;  ///< (dN_a/dx, dN_a/dz)
  StrainDisplacementMatrix B;                        ///< 4 x 2n
  /// The measure of an integral at this point: det J r (axisymmetric, per radian) or det J.
  double measure() const { return det_j * radius; }
};

/// Kinematics at natural point `xi`. Throws ModelError naming the element and its body if
/// det J <= 0 (inverted or degenerate element) or, in axisymmetry, r <= 0 at the point.
/// Call only at interior points (e.g. Gauss points): B needs r > 0 in axisymmetry.
PointKinematics point_kinematics(const ElementGeometry& geometry, const Eigen::Vector2d& xi);

/// Position x(xi) of a natural point (valid anywhere, including the element boundary).
Eigen::Vector2d natural_to_physical(const ElementGeometry& geometry, const Eigen::Vector2d& xi);

}  // namespace cs::solver

#pragma once
// Geometric checks of a mesh: Jacobian determinants at corners and Gauss points, element sizes.

#include "solver/mesh/mesh.hpp"

namespace cs::solver {

/// The smallest Jacobian determinant det(d(x,z)/d(xi,eta)) of one element, over its four corners
/// and its Gauss points (2x2 for Q4, 3x3 for Q8), using the element's own shape functions.
double min_jacobian_determinant(const Mesh& mesh, int element);

/// The smallest of min_jacobian_determinant over all elements (+inf for an empty mesh).
double min_jacobian_determinant(const Mesh& mesh);

/// Throws MeshError naming the first element whose Jacobian determinant is not positive at a
/// corner or Gauss point, or whose connectivity refers to a missing node.
void check_mesh(const Mesh& mesh);

/// How the elements of a mesh meet along their sides (corner to corner).
struct MeshTopology {
  int n_interior_sides = 0;  ///< sides shared by two elements
  int n_boundary_sides = 0;  ///< sides of one element only
  double boundary_length =
      0.0;  ///< total length of the boundary sides (straight, corner to corner)
};

/// Counts shared and boundary sides. In a conforming mesh every side is shared by at most two
/// elements, traversed in opposite directions, and (for a region without holes meshed without
/// hanging nodes) the boundary length equals the region's perimeter: a hanging node shows up as
/// extra boundary length. Throws MeshError naming the side if three elements share one, or two
/// traverse it in the same direction (overlap or inversion).
MeshTopology mesh_topology(const Mesh& mesh);

/// Area of one element in the (x, z) plane (Gauss quadrature of det J; exact for Q4 and for Q8
/// with straight sides).
double element_area(const Mesh& mesh, int element);

/// A characteristic size of one element: the square root of its area.
double element_size(const Mesh& mesh, int element);

}  // namespace cs::solver

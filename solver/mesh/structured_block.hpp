#pragma once
// Structured quadrilateral meshes of one logically rectangular block.
//
// make_block meshes the axis-aligned rectangle [x0, x0 + size.x] x [z0, z0 + size.z] with
// nx x nz elements; make_mapped_block meshes the image of the unit square under a map, which is
// how the curved indenters are built. Both number elements row by row (x fastest, then z) and
// give every element the counter-clockwise node order of mesh.hpp (det J > 0 for a map that
// preserves orientation). Q8 mid-side nodes sit at the image of the parametric side midpoint
// (the geometric side midpoint for make_block).
//
// Named sets (both generators; u, v are the logical axes, along x and z for make_block):
//   edge sets and node sets "left" (u = 0, x = x0), "right" (u = 1), "bottom" (v = 0, z = z0),
//   "top" (v = 1, z = z0 + size.z); node set "all". Node sets include Q8 mid-side nodes and are
//   sorted along their edge (by u for bottom/top, by v for left/right); edge sets likewise.
//   Element sides: bottom = side 0, right = side 1, top = side 2, left = side 3.

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"
#include "solver/mesh/spacing.hpp"

namespace cs::solver {

/// An axis-aligned rectangular block and how to divide it.
struct BlockSpec {
  ElementType type = ElementType::Q4;
  Eigen::Vector2d origin{0, 0};  ///< corner (x0, z0)
  Eigen::Vector2d size{1, 1};    ///< extents along x and z (> 0)
  int nx = 1;                    ///< elements along x (>= 1)
  int nz = 1;                    ///< elements along z (>= 1)
  Spacing x_spacing;             ///< node spacing along x
  Spacing z_spacing;             ///< node spacing along z
  std::string body_name = "body";
};

/// Meshes the block (one body, index 0, named spec.body_name). Throws MeshError on bad input.
Mesh make_block(const BlockSpec& spec);

/// A map of the unit square (u, v) in [0,1]^2 onto a physical region (x, z).
using BlockMap = std::function<Eigen::Vector2d(double u, double v)>;

/// A logically rectangular block: normalized node coordinates along u and v and the map.
struct MappedBlockSpec {
  ElementType type = ElementType::Q4;
  std::vector<double> u;  ///< node coordinates along u, 0 = u_0 < ... < u_nu = 1
  std::vector<double> v;  ///< node coordinates along v, 0 = v_0 < ... < v_nv = 1
  BlockMap map;           ///< (u, v) -> (x, z); must preserve orientation
  std::string body_name = "body";
};

/// Meshes the mapped block (one body). Throws MeshError on bad coordinates, a missing map, or an
/// element whose corner Jacobian is not positive (a map that folds or reverses orientation).
Mesh make_mapped_block(const MappedBlockSpec& spec);

}  // namespace cs::solver

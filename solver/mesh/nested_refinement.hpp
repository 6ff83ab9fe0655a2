#pragma once
// A rectangle meshed with square background cells and refined toward a point or a segment of its
// surface edge by nested boxes of 3:1 refinement, joined by conforming quadrilateral transition
// elements.
//
// Geometry. The rectangle is [x0, x0 + nx H0] x [z0, z0 + nz H0]; its "surface" is the edge
// z = z0 and the refined segment is [refine_x_min, refine_x_max] x {z0} (a point if the two are
// equal). Level 0 is the background grid of cell size H0. Level l (1..levels) splits the cells of
// a box of level-(l-1) cells into 3 x 3 cells of size H_l = H0 / 3^l. The box of level l holds the
// level-(l-1) cells that meet
//     [refine_x_min - box_padding H_{l-1}, refine_x_max + box_padding H_{l-1}]
//       x [z0, z0 + box_depth H_{l-1}],
// shrunk where needed to stay one level-(l-1) cell inside the box of level l-1 (except along the
// rectangle's own edges), so that no cell ever meets cells more than one level finer. With
// surface_strip_cells > 0, the box of level 1 is instead the whole strip of that many background
// cells along the surface (used for an indenter whose background is three times coarser than the
// indented body's: its level-l boxes are then the body's level-(l-1) boxes, node for node).
//
// Transition. An unrefined cell that shares one side with a refined box is split into four
// quadrilaterals: with the shared side as its local bottom [0, S] x {0} (split at S/3 and 2S/3
// by the three fine cells beside it) and interior nodes at (S/3, S/2), (2S/3, S/2):
//
//     T0 +-----------------+ T1        quads: (A0, A1, I1, T0), (A1, A2, I2, I1),
//        | \             / |                  (A2, A3, T1, I2), (I1, I2, T1, T0)
//        |  I1 -------- I2 |
//        |  |     |      | |         All four are convex (smallest angle about 34 degrees);
//     A0 +--A1----A2-----+-A3        cells diagonal to a box need no transition.
//
// Every node lies on a lattice of spacing H0 / (2 3^levels), so nodes are shared exactly.
//
// Sets: edge and node sets "left" (x = x0), "right", "bottom" (z = z0, the refined surface),
// "top" (z = z0 + nz H0), node set "all"; sorted along their edge. Elements are Q4; refine with
// refine_uniformly and convert with to_quadratic (mesh_transform.hpp).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {

/// The most nested 3:1 refinements a mesh takes (its finest cells are H0 / 3^12).
inline constexpr int kMaxRefinementLevels = 12;

/// Input of make_nested_refinement (see the file comment for the construction).
struct NestedRefinementSpec {
  Eigen::Vector2d origin{0, 0};  ///< corner (x0, z0); the refined surface is z = z0
  double cell_size = 1.0;        ///< background cell size H0 (> 0)
  int nx = 1;                    ///< background cells along x (>= 1)
  int nz = 1;                    ///< background cells along z (>= 1)
  double refine_x_min = 0.0;     ///< refined surface segment [refine_x_min, refine_x_max],
  double refine_x_max = 0.0;     ///< within [x0, x0 + nx H0]
  int levels = 0;                ///< number of nested 3:1 refinements (0 to kMaxRefinementLevels)
  double box_padding = 3.0;      ///< box reach beyond the segment, in cells of the level refined
  double box_depth = 3.0;        ///< box depth, in cells of the level being refined (> 0)
  int surface_strip_cells = 0;   ///< > 0: level 1 refines the whole surface strip this deep
  /// x positions to make node lines exactly (e.g. the contact edge x = a): each one strictly
  /// inside the finest box moves the nearest finest-level node line onto it, by a piecewise-linear
  /// map of x across the finest box. A target is ignored if it shares its nearest line with
  /// another target or if the map would stretch or shrink any interval by more than 2x.
  std::vector<double> snap_x;
  std::string body_name = "body";
};

/// One refinement box: its level, cell size, and extent [x_min, x_max] x [z_min, z_max].
struct RefinementBox {
  int level = 0;
  double cell_size = 0.0;  ///< H_level, the size of the cells inside the box
  double x_min = 0, x_max = 0, z_min = 0, z_max = 0;
  int n_cells = 0;  ///< cells of size H_level inside the box
};

/// What make_nested_refinement will build: counts and boxes (box 0 is the whole rectangle).
struct NestedRefinementLayout {
  int n_elements = 0;                ///< quadrilaterals, transitions included
  int n_transition_cells = 0;        ///< cells split by the transition template (4 quads each)
  double finest_size = 0.0;          ///< H0 / 3^levels
  std::vector<RefinementBox> boxes;  ///< boxes[l] is level l; boxes[0] the background
};

/// Plans the refinement without building nodes (cheap: use it to search for parameters).
/// Throws MeshError on bad input or when a box would vanish or leave its parent box.
NestedRefinementLayout plan_nested_refinement(const NestedRefinementSpec& spec);

/// Builds the Q4 mesh (one body). Throws MeshError as plan_nested_refinement does.
Mesh make_nested_refinement(const NestedRefinementSpec& spec);

}  // namespace cs::solver

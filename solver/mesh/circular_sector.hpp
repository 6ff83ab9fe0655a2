#pragma once
// Structured meshes of the quarter of a circular region in the (x, z) plane, x >= 0, z >= 0:
// a quarter annulus ri < r < ro (a ring or a spherical shell in section) and a quarter disc
// r < R (a shaft or a solid sphere). Both are curved: every node of an arc lies on it (Q8
// mid-side nodes too), so the conformal contact of a shaft in a ring is met node for node when
// both arcs are divided alike.
//
// Quarter annulus: one mapped block, u radial, v along the arc (theta = v pi/2, counter-
// clockwise from the x axis). Radii grow geometrically, r_i = ri (ro/ri)^(i/n_radial), so the
// elements stay about square from the bore to the outer face.
// Quarter disc: three mapped blocks welded at their shared nodes (solver/mesh/mesh_weld.hpp),
// so that no element degenerates at the centre or on the arc: a core square [0, s]^2,
// s = core_fraction R, divided n_arc/2 x n_arc/2, and two curved blocks from its right and top
// sides out to the arc (theta in [0, pi/4] and [pi/4, pi/2], n_arc/2 elements along the arc and
// n_radial across, nodes on straight lines from the square's side to the arc).
//
// Sets (edge sets and same-named node sets, sorted along the set; node set "all"):
//   annulus: "inner" (r = ri), "outer" (r = ro), "x_axis" (z = 0), "z_axis" (x = 0);
//   disc:    "arc" (r = R), "x_axis" (z = 0), "z_axis" (x = 0).
// The arcs' node sets are sorted by x (sort_along_set); the nodes of an arc are at the angles
// theta_k = k pi / (2 n_arc) (Q8: also the mid-side angles), the same in both generators.

#include <string>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {

/// A quarter annulus ri < r < ro, 0 <= theta <= pi/2.
struct QuarterAnnulusSpec {
  ElementType type = ElementType::Q4;
  double inner_radius = 1.0;  ///< ri > 0
  double outer_radius = 2.0;  ///< ro > ri
  int n_arc = 16;             ///< elements along the arcs (>= 1)
  int n_radial = 8;           ///< elements across (>= 1), sizes growing geometrically outward
  std::string body_name = "ring";
};

/// Meshes the quarter annulus (one body). Throws MeshError on bad radii or counts.
Mesh make_quarter_annulus(const QuarterAnnulusSpec& spec);

/// A quarter disc r < R, 0 <= theta <= pi/2.
struct QuarterDiscSpec {
  ElementType type = ElementType::Q4;
  double radius = 1.0;         ///< R > 0
  int n_arc = 16;              ///< elements along the arc (even, >= 2)
  int n_radial = 4;            ///< elements from the core square to the arc (>= 1)
  double core_fraction = 0.5;  ///< side of the core square over R, in (0, 1/sqrt(2))
  std::string body_name = "disc";
};

/// Meshes the quarter disc (one body). Throws MeshError on a bad radius, an odd or too small
/// n_arc, n_radial < 1 or a core square that does not fit inside the arc.
Mesh make_quarter_disc(const QuarterDiscSpec& spec);

/// The number of radial elements of a quarter annulus ri < r < ro whose elements at the bore are
/// about square for n_arc elements along the arc: ceil(ln(ro/ri) / ln(1 + pi/(2 n_arc))), at
/// least 2.
int square_radial_count(double inner_radius, double outer_radius, int n_arc);

}  // namespace cs::solver

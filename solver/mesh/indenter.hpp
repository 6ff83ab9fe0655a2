#pragma once
// Indenter bodies: the profile of the surface that touches the indented body and quadrilateral
// meshes of the indenter above it.
//
// Frame: z points into the indented body, whose surface is z = 0; the indenter lies in z <= 0.
// A profile gives the indenter's lower (contact) surface z = profile(x) <= 0 for
// 0 <= x <= half_width, touching z = 0 at x = 0 (x = 0 is the symmetry line or axis). The
// indenter is the region profile(x) >= z >= -height over 0 <= x <= half_width: its back face
// z = -height is where a load or a displacement is applied.
//
// Meshes are built flat, on [0, half_width] x [-height, 0], and then wrapped onto the profile by
// moving every corner node vertically: z -> z + profile(x) (1 + z / height). Columns stay
// vertical, the back face stays flat, and surface nodes land on the profile at the x they had,
// so they line up with indented-body nodes at the same x. Q8 mid-side nodes: at the midpoints of
// the wrapped corners inside the indenter; on the contact surface, on the profile straight below
// the side's x-midpoint where the surface is gentle (|slope| <= 1/2: the contact zone, where they
// line up with the indented body's mid-side nodes), else at the profile point nearest the chord
// midpoint (where the rounded punch turns vertical, so that det J stays positive).
//
// Sets of an indenter mesh (edge and node sets): "contact" (the profile), "back"
// (z = -height), "left" (x = 0), "right" (x = half_width); node set "all".

#include <functional>
#include <string>
#include <vector>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"
#include "solver/mesh/spacing.hpp"

namespace cs::solver {

/// The lower surface z = z_of_x(x) <= 0 of an indenter over 0 <= x <= half_width.
struct IndenterProfile {
  std::function<double(double)> z_of_x;
  double half_width = 1.0;
  std::string name;  ///< e.g. "cylinder R = 2"
};

/// A flat face z = 0 of the given half-width: the patch-test block and the sharp-cornered punch.
IndenterProfile flat_profile(double half_width);

/// A circle of radius R through the origin: z = -(R - sqrt(R^2 - x^2)) for 0 <= x <= half_width
/// (half_width <= R): the cylinder (plane strain) or sphere (axisymmetric) of the Hertz problems.
IndenterProfile circle_profile(double radius, double half_width);

/// A flat punch with rounded edges: flat (z = 0) for x <= b, then a quarter circle of radius r_e,
/// z = -(r_e - sqrt(r_e^2 - (x - b)^2)) for b <= x <= b + r_e (half_width = b + r_e; the
/// surface is vertical at x = b + r_e). The Steuermann problem's punch.
IndenterProfile rounded_punch_profile(double b, double r_e);

/// Moves the nodes of a flat indenter mesh on [0, half_width] x [-height, 0] onto the profile (see
/// the file comment; a Q8 mesh needs its edge set "contact"). Throws MeshError if
/// height <= -min profile (the map would fold).
void wrap_onto_profile(Mesh& mesh, const IndenterProfile& profile, double height);

/// A structured indenter mesh: columns at given surface x positions, rows graded toward the
/// contact surface.
struct IndenterSpec {
  ElementType type = ElementType::Q4;
  IndenterProfile profile;
  /// x of the surface nodes (corner nodes), increasing, 0 first and profile.half_width last.
  std::vector<double> surface_x;
  double height = 1.0;      ///< back face at z = -height (> -min profile)
  int n_rows = 1;           ///< elements through the height
  double row_growth = 1.0;  ///< size ratio of successive rows going away from the contact (> 0)
  std::string body_name = "indenter";
};

/// Builds the structured indenter (one body). Throws MeshError on bad input.
Mesh make_indenter(const IndenterSpec& spec);

/// Renames the sets of a flat block mesh (make_block / make_nested_refinement conventions, with
/// the contact surface at z = z_max = 0) to the indenter's: top -> contact, bottom -> back.
void name_indenter_sets(Mesh& mesh);

}  // namespace cs::solver

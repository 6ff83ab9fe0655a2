#pragma once
// The meshes of the study's problems (its Figure 3 and Table 1): the indented body and the
// indenter, per problem, mesh level and element type, merged into one solver::Mesh.
//
// Frame (as in the study): z points into the indented body, whose contact surface is z = 0;
// the indenter sits in z <= 0. x = 0 is the symmetry line (plane strain) or the axis
// (axisymmetric, x = r). Only the half x >= 0 is meshed.
//
// Which family builds a problem's mesh, the block's size and its element count are the
// problem's MeshLayout (suites/mesh_layout.hpp, in its descriptor). The study's problems:
//
// Indented body ("block", body 0), as Table 1 counts it:
//   P, P'  0 < x < a,  0 < z < h (h = a by default)   8x8 / 10x10 elements at C, uniform
//   H_p    0 < x < 4a, 0 < z < 4a                     16x16 at C, uniform
//   H_a    0 < r < 8a, 0 < z < 8a                     16x16 at C, uniform
//   F      0 < x < 4a, 0 < z < 4a                     32x32 at C, uniform
//   S      0 < x < 8b, 0 < z < 8b                     graded toward the contact edge, see below
// M and F meshes halve every element side of C (4x and 16x the elements), as the study did.
//
// Indenter ("indenter", body 1): P, P' a block of half-width a; H a circle segment of radius R
// (cylinder or sphere) of half-width 2a; F a flat punch of half-width a with sharp corners; S a
// flat punch of half-width b with edges rounded to radius r_e (half-width b + r_e). Its surface
// nodes sit at the block's surface node x positions (so they match exactly where the surfaces
// touch, and nearly match on the curved H and S profiles), except for P', whose indenter surface
// is divided into a different number of elements (by default one fewer than the block's) so
// that only the end nodes line up.
//
// Steuermann (S) mesh: a uniform background grid of N x N square cells of size H0 = 8b/N with
// `levels` nested 3:1 refinements (solver/mesh/nested_refinement.hpp) of boxes around the
// surface band [b, a] between the end of the punch's flat and the contact edge, reaching
// `box_padding` cells beyond the band and `box_depth` cells deep at each level, so the
// smallest elements, of size H0 / 3^levels, cover the band. levels is the least number (>= 1)
// that puts at least `band_elements` smallest elements across b < x < a; N is then the one whose
// C-level count is nearest the study's (Table 1), which keeps the mesh "largely uniform" as the
// study says its meshes were. Node lines are moved onto x = b and x = a exactly. The indenter
// uses the same boxes (a background three times coarser, refined once along its whole contact
// face), so its contact nodes coincide with the block's for 0 <= x <= a.

#include <string>
#include <vector>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/nested_refinement.hpp"
#include "suites/case_spec.hpp"

namespace cs::suites {

/// Names of the bodies and sets of every study mesh (edge sets and node sets of the same name;
/// node sets sorted along their edge, and "block.all", "indenter.all").
namespace study_sets {
inline constexpr const char* kBlock = "block";                   ///< body 0: the indented body
inline constexpr const char* kIndenter = "indenter";             ///< body 1: the indenter
inline constexpr const char* kBlockContact = "block.contact";    ///< z = 0, whole block width
inline constexpr const char* kBlockSymmetry = "block.symmetry";  ///< x = 0 (symmetry or axis)
inline constexpr const char* kBlockFarX = "block.far_x";         ///< x = block width
inline constexpr const char* kBlockFarZ = "block.far_z";  ///< z = block depth (P: loaded face)
inline constexpr const char* kIndenterContact = "indenter.contact";    ///< the profile
inline constexpr const char* kIndenterLoad = "indenter.load";          ///< back face z = -height
inline constexpr const char* kIndenterSymmetry = "indenter.symmetry";  ///< x = 0
inline constexpr const char* kIndenterSide = "indenter.side";          ///< x = half-width
}  // namespace study_sets

/// Choices the study leaves open; the defaults are the suite's.
struct StudyMeshOptions {
  double patch_height_over_a = 1.0;            ///< P, P': slab height h / a
  double patch_indenter_height_over_a = 0.25;  ///< P, P': indenter height / a
  int pprime_indenter_elements = 0;            ///< P': indenter surface elements (0: block's - 1)
  double hertz_indenter_half_width_over_a = 2.0;  ///< H: indenter half-width / a
  double hertz_indenter_height_over_a = 1.0;      ///< H: indenter height at x = 0, over a
  double punch_indenter_height_over_a = 0.5;      ///< F: indenter height / a
  int steuermann_band_elements = 6;     ///< S: least smallest elements across b < x < a (C)
  double steuermann_box_padding = 3.0;  ///< S: box reach beyond [b, a], in parent cells
  double steuermann_box_depth = 3.0;    ///< S: box depth, in parent cells
  int steuermann_target_elements = 0;   ///< S: C-level block count aimed at; 0: Table 1
  double steuermann_indenter_height_over_re = 1.5;  ///< S: indenter height / r_e (at least)
};

/// What to build. Lengths in any consistent unit.
struct StudyMeshSpec {
  ProblemId problem = ProblemId::P_p;
  MeshLevel level = MeshLevel::C;
  ElementType element = ElementType::Q4;
  double a = 1.0;    ///< contact half-width (S: from Eq. 32, computed by the caller; a > b)
  double R = 0.0;    ///< H: indenter radius (> indenter half-width)
  double b = 0.0;    ///< S: half-width of the punch's flat face
  double r_e = 0.0;  ///< S: edge radius of the punch
  StudyMeshOptions options;
  /// H, S, F: the block's width and depth over the study's (>= 1). Beyond half the study's
  /// extent the block is stretched outwards (solver/mesh/far_field_stretch.hpp); nearer the
  /// contact the mesh is the study's. P and P' take 1 only.
  double extent = 1.0;
};

/// Description of a built study mesh.
struct StudyMeshInfo {
  int n_block_elements = 0;  ///< the count Table 1 reports
  int n_indenter_elements = 0;
  int n_nodes = 0;
  int table1_block_elements = 0;  ///< Table 1's count (S: for r_e/b; interpolated off the study)
  double block_width = 0.0;       ///< block extent along x
  double block_depth = 0.0;       ///< block extent along z
  double indenter_half_width = 0.0;
  double indenter_height = 0.0;  ///< back face at z = -indenter_height
  /// Characteristic element size h at the contact: the shortest block.contact side with
  /// x <= a (uniform meshes: the element side; S: the smallest size, at the contact edge).
  double h_contact = 0.0;
  double h_background = 0.0;  ///< the block's typical (background) element side
  int indenter_surface_elements = 0;
  // S only (zero otherwise), for the C-level layout before halving:
  int steuermann_background_cells = 0;                  ///< N: background cells along each side
  int steuermann_levels = 0;                            ///< nested 3:1 refinements
  std::vector<solver::RefinementBox> steuermann_boxes;  ///< at C, box 0 the background
};

/// A built study mesh: the merged two-body mesh and its description.
struct StudyMesh {
  solver::Mesh mesh;
  StudyMeshInfo info;
};

/// Builds the mesh of `spec`. Throws SuiteInputError for bad geometry (non-positive lengths, an
/// S problem without b < a < b + r_e, an H radius too small for the indenter) and lets
/// solver::MeshError through from the generators.
StudyMesh build_study_mesh(const StudyMeshSpec& spec);

/// Table 1 of the study: elements of the indented body for a problem and level (the count its
/// descriptor's MeshLayout gives for C, times 4 per level; 0 beyond the study and for VF).
int table1_elements(ProblemId problem, MeshLevel level);

/// The S count aimed at for any r_e/b: Table 1 at 1, 1/3 and 1/7; between them, interpolated
/// linearly in ln(r_e/b); outside, the nearest end's value.
int steuermann_target_elements(double re_over_b, MeshLevel level);

/// 1, 2, 4 for C, M, F: the factor by which element sides are divided relative to C.
int level_factor(MeshLevel level);

}  // namespace cs::suites

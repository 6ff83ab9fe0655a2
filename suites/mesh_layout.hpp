#pragma once
// How a problem's two bodies are meshed (suites/study_meshes.hpp): which of the study's mesh
// families builds them, the block's size over the problem's length, its elements at level C
// and the study's Table 1 count. One value per problem, in its descriptor.

namespace cs::suites {

/// The mesh generator of a problem.
enum class MeshFamily {
  patch,             ///< P: a uniform slab under a flat block indenter whose nodes match the slab's
  mismatched_patch,  ///< P': the same, the indenter's surface divided differently
  hertz,             ///< H: a uniform square block under a circular indenter
  flat_punch,        ///< F: a uniform square block under a flat punch with sharp corners
  steuermann,        ///< S: a block refined towards the contact edge, under a rounded punch
  own,               ///< the problem builds its own mesh (CM, IF): build_study_mesh refuses it
};

/// The layout of a problem's study mesh. An aggregate without defaults: a descriptor names all.
struct MeshLayout {
  MeshFamily family;
  /// The block's width (and, but for the patches, depth) over a: P 1, H_p 4, H_a 8, F 4; 0 for
  /// the families that size their block themselves (S: 8 b; own).
  double block_side_over_a;
  /// Elements along each side of a uniform block at level C (P 8, P' 10, H 16, F 32); 0 for S
  /// (planned from Table 1) and own.
  int elements_per_side;
  /// The study's Table 1 count of block elements at level C; 0 for a problem beyond the study.
  int table1_elements;
};

}  // namespace cs::suites

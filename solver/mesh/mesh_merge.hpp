#pragma once
// Merging meshes of separate bodies into one Mesh (e.g. the indented block and its indenter).

#include <vector>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {

/// Concatenates the parts into one mesh; no nodes are shared, so the bodies stay separate.
///
/// Nodes, elements and sets of part k follow those of parts 0..k-1; element and node indices and
/// body indices are offset accordingly, so every element keeps its body. The sets of a one-body
/// part are prefixed with its body name and a dot ("bottom" of body "indenter" becomes
/// "indenter.bottom"); the sets of a part with several bodies keep their names (they are taken to
/// be prefixed already). Throws MeshError if the parts differ in element type, if two bodies share
/// a name, or if two sets end up with the same name.
Mesh merge_bodies(const std::vector<Mesh>& parts);

}  // namespace cs::solver

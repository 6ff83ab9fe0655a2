#pragma once
// Welding the blocks of one body: meshes generated side by side whose shared boundaries carry
// nodes at the same positions become one conforming mesh.

#include <string>
#include <vector>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {

/// Concatenates the parts (one element type) into one body named `body_name`, with the nodes
/// closer than `tolerance` merged into one (the first part's index kept). The parts' sets are
/// dropped (the caller names the welded body's sets); the node set "all" holds every node.
/// Throws MeshError for no parts, mixed element types or a non-positive tolerance.
Mesh weld_blocks(const std::vector<Mesh>& parts, const std::string& body_name, double tolerance);

}  // namespace cs::solver

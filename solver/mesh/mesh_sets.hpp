#pragma once
// Named node and edge sets of a Mesh: checked lookup, renaming, derived node sets, sorting.
//
// Convention used by every generator in solver/mesh: a node set with the same name as an edge set
// holds exactly the nodes of that edge set (corners and Q8 mid-side nodes), sorted along the edge.
// Mesh operations that change nodes (refinement, Q4 -> Q8) rebuild such node sets from their edge
// sets; the node set "all" is rebuilt to hold every node.

#include <functional>
#include <string>
#include <vector>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {

/// The node set `name`; throws MeshError "unknown node set 'name' (known: ...)" if absent.
const std::vector<int>& node_set(const Mesh& mesh, const std::string& name);

/// The edge set `name`; throws MeshError "unknown edge set 'name' (known: ...)" if absent.
const std::vector<ElementSide>& edge_set(const Mesh& mesh, const std::string& name);

/// The distinct nodes of the sides of edge set `name` (Q8 mid-side nodes included), sorted
/// along x (ties by z). Throws MeshError if the set is unknown or empty.
std::vector<int> edge_set_nodes_sorted_along_x(const Mesh& mesh, const std::string& name);

/// The nodes of `nodes` sorted along the direction in which they spread most: by x (then z) if
/// their x-extent is at least their z-extent, else by z (then x).
std::vector<int> sort_along_set(const Mesh& mesh, std::vector<int> nodes);

/// Sorts the sides of an edge set by the same rule, applied to the sides' midpoints.
void sort_edge_set(const Mesh& mesh, std::vector<ElementSide>& sides);

/// The distinct nodes of `sides`, sorted along the set (sort_along_set).
std::vector<int> nodes_of_sides(const Mesh& mesh, const std::vector<ElementSide>& sides);

/// Sets node set `name` to the nodes of edge set `name` (sorted along the set).
void set_node_set_from_edge_set(Mesh& mesh, const std::string& name);

/// Rebuilds every node set that has a same-named edge set, and the node set "all".
void rebuild_edge_node_sets(Mesh& mesh);

/// Renames node set and edge set `from` (whichever exist) to `to`. Throws MeshError if neither
/// exists or if `to` is already taken.
void rename_set(Mesh& mesh, const std::string& from, const std::string& to);

/// The boundary sides of the mesh (sides that belong to exactly one element), sorted by element
/// then side.
std::vector<ElementSide> boundary_sides(const Mesh& mesh);

/// The boundary sides whose nodes all satisfy `on` (e.g. "lies on x = 0"), sorted along the set.
std::vector<ElementSide> boundary_sides_where(
    const Mesh& mesh, const std::function<bool(const Eigen::Vector2d&)>& on);

/// The nodes satisfying `predicate`, in index order.
std::vector<int> nodes_where(const Mesh& mesh,
                             const std::function<bool(const Eigen::Vector2d&)>& predicate);

}  // namespace cs::solver

#pragma once
// Operations that turn one mesh into another: uniform refinement, Q4 -> Q8, mirroring, mapping.
// All of them keep bodies, edge sets (sides are carried to the new elements) and node sets (see
// mesh_sets.hpp for how node sets that belong to an edge set are rebuilt).

#include <functional>

#include "solver/mesh/mesh.hpp"
#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {

/// Splits every element of a Q4 mesh into k x k elements (k >= 1) by bilinear interpolation of its
/// corners: the "halve every element side" refinement of the study for k = 2. Straight sides are
/// split at the same points from both elements, so a conforming mesh stays conforming. Existing
/// nodes keep their indices. Element e's children are numbered e*k*k + j*k + i (i along its side
/// 0, j along its side 3 reversed). Throws MeshError for a Q8 mesh or k < 1.
Mesh refine_uniformly(const Mesh& mesh, int k);

/// Turns a Q4 mesh into a Q8 mesh: one mid-side node at the midpoint of every distinct side,
/// shared by the elements on both sides of it. Existing nodes keep their indices. Throws
/// MeshError for a mesh that is already Q8.
Mesh to_quadratic(const Mesh& mesh);

/// Moves every node p to map(p) (elements and sets unchanged). The caller keeps the map
/// orientation-preserving; check_mesh (mesh_quality.hpp) tells if it did not.
void map_nodes(Mesh& mesh, const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& map);

/// Reflects the mesh in the plane z = 0 (z -> -z) and reorders each element's nodes so that it
/// stays counter-clockwise; the sides of edge sets are renumbered to match.
void mirror_z(Mesh& mesh);

}  // namespace cs::solver

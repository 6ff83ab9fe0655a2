#pragma once
// The sides of an edge set as an ordered path: its nodes in order along the surface, with arc
// lengths. Used to report quantities "along a surface" and available to contact.
//
// When the sides form one chain (an open polyline or a closed loop, each corner shared by at
// most two sides) the path follows it, from the end with the smaller position (x, then z):
// a block's top or bottom runs in +x, its left or right side in +z. A closed loop starts at
// its smallest corner and follows the direction of that corner's first side. Otherwise
// (branches, several pieces) the nodes are sorted by position, x then z, and is_chain is false.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/mesh/mesh.hpp"

namespace cs::solver {

struct SurfacePath {
  std::string edge_set;
  bool is_chain = true;    ///< the sides form one chain
  bool closed = false;     ///< the chain is a closed loop (first node not repeated at the end)
  std::vector<int> nodes;  ///< in path order (corners and Q8 mid-side nodes)
  std::vector<Eigen::Vector2d> positions;  ///< node coordinates, same order
  std::vector<double> arc_length;          ///< along the path (chords between nodes), from 0
  std::vector<ElementSide> sides;          ///< in path order
  std::vector<bool> reversed;              ///< side runs against the path direction
  std::vector<double> side_start;          ///< arc length where each side begins (path order)
  std::vector<double> side_length;         ///< chord length of each side along the path
};

/// The path of edge set `edge_set`. Throws ModelError if the set is unknown or empty.
SurfacePath surface_path(const Mesh& mesh, const std::string& edge_set);

}  // namespace cs::solver

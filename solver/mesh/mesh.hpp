#pragma once
// The 2D finite-element mesh: nodes, quadrilateral elements, bodies, named node and edge sets.
//
// Coordinates are (x, z) in plane strain and (r, z) in axisymmetry; the axis of symmetry is
// x = r = 0 and axisymmetric meshes must lie in r >= 0. The solver attaches no meaning to the
// direction of z (the suites let z point into the indented body, as the study does).
//
// Element node order (counter-clockwise in the (x, z) plane, so det J > 0):
//   Q4: corners 0,1,2,3.
//   Q8: corners 0,1,2,3, then mid-side nodes 4 (side 0-1), 5 (1-2), 6 (2-3), 7 (3-0).
// Local side s (0..3) runs from corner s to corner (s+1)%4; for Q8 its mid-side node is 4+s.

#include <array>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cs::solver {

/// The element family of a mesh: one per mesh.
enum class ElementType {
  Q4,  ///< 4-node bilinear quadrilateral, 2x2 Gauss quadrature
  Q8,  ///< 8-node serendipity quadrilateral, 3x3 Gauss quadrature
};

/// Number of nodes of an element of the given type.
constexpr int nodes_per_element(ElementType type) {
  return type == ElementType::Q4 ? 4 : 8;
}

/// Number of nodes on one side of an element of the given type (2 for Q4, 3 for Q8).
constexpr int nodes_per_side(ElementType type) {
  return type == ElementType::Q4 ? 2 : 3;
}

/// One side of one element: the unit in which edge sets, tractions and contact surfaces are given.
struct ElementSide {
  int element = 0;  ///< element index
  int side = 0;     ///< local side 0..3 (see the file comment)
  bool operator==(const ElementSide&) const = default;
};

/// A mesh of one element type, possibly of several bodies (e.g. indenter and indented block).
struct Mesh {
  ElementType type = ElementType::Q4;
  std::vector<Eigen::Vector2d> nodes;                 ///< node coordinates (x|r, z)
  std::vector<std::array<int, 8>> elements;           ///< connectivity; Q4 uses the first 4 entries
  std::vector<int> element_body;                      ///< body index of each element
  std::vector<std::string> body_names;                ///< name of each body, indexed by body index
  std::map<std::string, std::vector<int>> node_sets;  ///< named sets of node indices
  std::map<std::string, std::vector<ElementSide>> edge_sets;  ///< named sets of element sides

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_elements() const { return static_cast<int>(elements.size()); }
  int n_element_nodes() const { return nodes_per_element(type); }

  /// Node indices of local side `side` of element `element`, in the side's direction
  /// (corner s, corner s+1, and for Q8 the mid-side node last).
  std::array<int, 3> side_nodes(const ElementSide& s) const {
    const auto& e = elements[s.element];
    return {e[s.side], e[(s.side + 1) % 4], type == ElementType::Q8 ? e[4 + s.side] : -1};
  }
};

}  // namespace cs::solver

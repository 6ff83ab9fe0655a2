#pragma once
// A contact surface: the sides of a named edge set of a meshed body, as contact segments.
//
// Segment k is local side s of a host element (Q4: 2 nodes, Q8: 3 nodes in Mesh::side_nodes
// order: corner s, corner s+1, mid-side), parametrized by the side coordinate t in [-1, 1]
// (t = -1 at corner s) with the side shape functions of solver/elements/shape_functions.hpp.
// The normal of a segment is the unit outward normal of its host element (sides run
// counter-clockwise, so n = (x'_z, -x'_x) / |x'|).
//
// What contact takes from the host element:
//   - the underlying element depth h = (host element area) / (length of the side), the size of
//     the element normal to the surface (the element's corner quadrilateral area);
//   - the Young's modulus E of the host element's body.
// The penalty stiffness scale of a contact point with tributary measure w is E w / h (see
// solver/contact/constraint_set.hpp).
//
// In axisymmetry the measure of a surface integral is r ds (per radian); in plane strain ds.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "solver/analysis_type.hpp"
#include "solver/elements/shape_functions.hpp"
#include "solver/mesh/mesh.hpp"
#include "solver/model.hpp"

namespace cs::solver {

/// One contact segment: an element side and what contact needs of its host element.
struct ContactSegment {
  ElementSide side;                      ///< host element and its local side
  int n_nodes = 2;                       ///< 2 (Q4) or 3 (Q8)
  std::array<int, 3> nodes{-1, -1, -1};  ///< node indices, Mesh::side_nodes order
  std::array<Eigen::Vector2d, 3> x{};    ///< node coordinates, same order
  double depth_h = 0.0;                  ///< underlying element depth (area / side length)
  double youngs_modulus_E = 0.0;         ///< E of the host element's body
};

/// The segments of one edge set, with the geometry contact needs.
class ContactSurface {
 public:
  /// The sides of edge set `edge_set` of `model.mesh`. `role` names the surface in messages
  /// ("contact surface" or "target surface"). Throws ContactError if the set does not exist,
  /// is empty, refers to a missing element or side, or a host element has a non-positive area.
  ContactSurface(const Model& model, const std::string& edge_set,
                 const std::string& role = "contact surface");

  const std::string& name() const { return name_; }
  ElementType element_type() const { return type_; }
  AnalysisType analysis() const { return analysis_; }
  int n_segments() const { return static_cast<int>(segments_.size()); }
  const std::vector<ContactSegment>& segments() const { return segments_; }
  const ContactSegment& segment(int k) const { return segments_[k]; }
  /// The nodes of the surface (corners and Q8 mid-side nodes), sorted, unique.
  const std::vector<int>& nodes() const { return nodes_; }
  /// The reference position of every node of the surface, parallel to nodes().
  const std::vector<Eigen::Vector2d>& node_positions() const { return node_positions_; }

  /// Side shape functions of segment k at t.
  SideShapeValues shape(int k, double t) const;
  /// Position x(t) of segment k.
  Eigen::Vector2d point(int k, double t) const;
  /// Tangent dx/dt of segment k (not normalized).
  Eigen::Vector2d tangent(int k, double t) const;
  /// Unit outward normal of segment k's host element at t.
  Eigen::Vector2d normal(int k, double t) const;
  /// Measure of a surface integral at t per unit dt: |dx/dt| (plane strain) or |dx/dt| r
  /// (axisymmetric, per radian).
  double measure(int k, double t) const;
  /// The side coordinate t in [-1, 1] of the point of segment k closest to p.
  double closest_parameter(int k, const Eigen::Vector2d& p) const;
  /// The distance from p to segment k's node bounding box (0 inside): a cheap lower bound of
  /// the distance from p to the segment for straight segments, and close to it otherwise.
  double box_distance(int k, const Eigen::Vector2d& p) const;

 private:
  std::string name_;
  ElementType type_ = ElementType::Q4;
  AnalysisType analysis_ = AnalysisType::PlaneStrain;
  std::vector<ContactSegment> segments_;
  std::vector<int> nodes_;
  std::vector<Eigen::Vector2d> node_positions_;
  std::vector<Eigen::AlignedBox2d> boxes_;
};

}  // namespace cs::solver

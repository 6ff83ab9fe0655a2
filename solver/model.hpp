#pragma once
// The linear-elastic model handed to the solver: mesh, analysis type, one material per body,
// prescribed displacements and loads, all as plain data and callables of position.
//
// Units are the caller's (consistent). Sign conventions: forces and tractions along +x|r and +z
// are positive; a pressure is positive when it pushes into the body (against the outward
// normal). In axisymmetry every force, traction integral and reaction is per radian (see
// solver/analysis_type.hpp).
//
// A contact pair (solver/contact/) is not part of this struct: it builds on a Model and its
// LinearStaticAnalysis (see solver/linear_static.hpp).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/analysis_type.hpp"
#include "solver/fields.hpp"
#include "solver/material.hpp"
#include "solver/mesh/mesh.hpp"

namespace cs::solver {

/// The nodes a constraint or a point force applies to: a named node set, the nodes of a named
/// edge set (corners and Q8 mid-side nodes), or an explicit list of node indices.
struct NodeSelection {
  enum class Kind { NodeSet, EdgeSet, Nodes };
  Kind kind = Kind::NodeSet;
  std::string name;        ///< set name (NodeSet, EdgeSet) or a label for the list (Nodes)
  std::vector<int> nodes;  ///< node indices (Nodes)

  static NodeSelection node_set(std::string name) { return {Kind::NodeSet, std::move(name), {}}; }
  static NodeSelection edge_set(std::string name) { return {Kind::EdgeSet, std::move(name), {}}; }
  static NodeSelection list(std::vector<int> nodes, std::string label = "node list") {
    return {Kind::Nodes, std::move(label), std::move(nodes)};
  }
  /// "node set 'left'", "edge set 'top'" or "node list 'label'", for messages.
  std::string describe() const;
};

/// u_component(x) = value(x) at every node of `where` (evaluated at the node's position).
struct PrescribedDisplacement {
  NodeSelection where;
  Component component = Component::X;
  ScalarField value;  ///< the prescribed value as a function of the node position
};

/// A traction t(x) (force per unit area, global components) on the sides of an edge set,
/// integrated consistently along each side: f_k = int N_k t r^[axi] ds.
struct EdgeTraction {
  std::string edge_set;
  VectorField traction;
  int gauss_points = 0;  ///< points per side (0: QuadratureOptions::edge_points)
};

/// A normal pressure p(x) on an edge set: the traction -p n with n the outward unit normal.
struct EdgePressure {
  std::string edge_set;
  ScalarField pressure;  ///< positive pushes into the body
  int gauss_points = 0;  ///< points per side (0: QuadratureOptions::edge_points)
};

/// A force on every node of `where` (per unit thickness | per radian).
struct PointForce {
  NodeSelection where;
  Eigen::Vector2d force = Eigen::Vector2d::Zero();
};

/// A body force b(x) (force per unit volume) on the elements of one body (or of all bodies).
struct BodyForce {
  VectorField force_density;
  int body = -1;  ///< body index, or -1 for every body
};

/// The loads of one load case. A model carries one; LinearStaticAnalysis can solve many
/// load cases with one factorization.
struct LoadCase {
  std::vector<EdgeTraction> tractions;
  std::vector<EdgePressure> pressures;
  std::vector<PointForce> point_forces;
  std::vector<BodyForce> body_forces;

  LoadCase& add_traction(std::string edge_set, VectorField traction, int gauss_points = 0);
  LoadCase& add_pressure(std::string edge_set, double pressure, int gauss_points = 0);
  LoadCase& add_pressure(std::string edge_set, ScalarField pressure, int gauss_points = 0);
  LoadCase& add_point_force(NodeSelection where, const Eigen::Vector2d& force);
  LoadCase& add_body_force(VectorField force_density, int body = -1);
};

/// Quadrature orders (Gauss points per direction); 0 selects the default.
struct QuadratureOptions {
  int element_points = 0;     ///< stiffness: 0 -> 2 (Q4), 3 (Q8)
  int body_force_points = 0;  ///< body forces: 0 -> element_points + 1
  int edge_points = 0;        ///< tractions along sides: 0 -> 5 (exact to degree 9)
};

/// The model: everything the linear solver needs.
struct Model {
  Mesh mesh;
  AnalysisType analysis = AnalysisType::PlaneStrain;
  std::vector<Material> materials;  ///< one per body, indexed like mesh.body_names
  std::vector<PrescribedDisplacement> prescribed;
  LoadCase loads;
  QuadratureOptions quadrature;

  /// Prescribes component `c` to the constant `value` on `where`.
  Model& fix(NodeSelection where, Component c, double value = 0.0);
  /// Prescribes component `c` to value(x) on `where`.
  Model& prescribe(NodeSelection where, Component c, ScalarField value);

  int n_bodies() const { return static_cast<int>(mesh.body_names.size()); }
  /// The index of the body called `name`; throws ModelError if there is none.
  int body_index(const std::string& name) const;

  int element_points() const;
  int body_force_points() const;
  int edge_points(int requested) const;
};

/// Checks everything that comes from input, once: mesh consistency (connectivity, bodies,
/// axisymmetric meshes in r >= 0), one valid material per body, every set named by a
/// constraint or load exists and is not empty, components and quadrature orders in range,
/// callables present. Throws ModelError with a one-line message naming the cause.
/// (Element Jacobians are checked where they are computed, during assembly.)
void validate(const Model& model);

/// Validates the loads of a load case against `model` (same checks as validate()).
void validate(const Model& model, const LoadCase& loads);

/// The node indices of a selection, sorted and unique. Throws ModelError if the set is unknown
/// or empty or a node index is out of range.
std::vector<int> resolve_nodes(const Mesh& mesh, const NodeSelection& where);

/// The sides of a named edge set. Throws ModelError if the set is unknown or empty or refers
/// to a missing element or side.
const std::vector<ElementSide>& resolve_edge_set(const Mesh& mesh, const std::string& name);

}  // namespace cs::solver

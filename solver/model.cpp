#include "solver/model.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "solver/elements/element_stiffness.hpp"
#include "solver/elements/gauss_rule.hpp"
#include "solver/model_error.hpp"

namespace cs::solver {

std::string NodeSelection::describe() const {
  switch (kind) {
    case Kind::NodeSet:
      return fmt::format("node set '{}'", name);
    case Kind::EdgeSet:
      return fmt::format("edge set '{}'", name);
    case Kind::Nodes:
      return fmt::format("node list '{}'", name);
  }
  return "selection";
}

LoadCase& LoadCase::add_traction(std::string edge_set, VectorField traction, int gauss_points) {
  tractions.push_back({std::move(edge_set), std::move(traction), gauss_points});
  return *this;
}

LoadCase& LoadCase::add_pressure(std::string edge_set, double pressure, int gauss_points) {
  return add_pressure(std::move(edge_set), constant_field(pressure), gauss_points);
}

LoadCase& LoadCase::add_pressure(std::string edge_set, ScalarField pressure, int gauss_points) {
  pressures.push_back({std::move(edge_set), std::move(pressure), gauss_points});
  return *this;
}

LoadCase& LoadCase::add_point_force(NodeSelection where, const Eigen::Vector2d& force) {
  point_forces.push_back({std::move(where), force});
  return *this;
}

LoadCase& LoadCase::add_body_force(VectorField force_density, int body) {
  body_forces.push_back({std::move(force_density), body});
  return *this;
}

Model& Model::fix(NodeSelection where, Component c, double value) {
  return prescribe(std::move(where), c, constant_field(value));
}

Model& Model::prescribe(NodeSelection where, Component c, ScalarField value) {
  prescribed.push_back({std::move(where), c, std::move(value)});
  return *this;
}

int Model::body_index(const std::string& name) const {
  for (int b = 0; b < n_bodies(); ++b) {
    if (mesh.body_names[b] == name)
      return b;
  }
  throw ModelError(fmt::format("unknown body '{}'", name));
}

int Model::element_points() const {
  return quadrature.element_points > 0 ? quadrature.element_points
                                       : default_gauss_points(mesh.type);
}

int Model::body_force_points() const {
  return quadrature.body_force_points > 0 ? quadrature.body_force_points : element_points() + 1;
}

int Model::edge_points(int requested) const {
  if (requested > 0)
    return requested;
  return quadrature.edge_points > 0 ? quadrature.edge_points : 5;
}

std::vector<int> resolve_nodes(const Mesh& mesh, const NodeSelection& where) {
  std::vector<int> nodes;
  switch (where.kind) {
    case NodeSelection::Kind::NodeSet: {
      const auto it = mesh.node_sets.find(where.name);
      if (it == mesh.node_sets.end()) {
        throw ModelError(fmt::format("unknown node set '{}'", where.name));
      }
      nodes = it->second;
      break;
    }
    case NodeSelection::Kind::EdgeSet: {
      for (const ElementSide& s : resolve_edge_set(mesh, where.name)) {
        for (int n : mesh.side_nodes(s)) {
          if (n >= 0)
            nodes.push_back(n);
        }
      }
      break;
    }
    case NodeSelection::Kind::Nodes:
      nodes = where.nodes;
      break;
  }
  if (nodes.empty()) {
    throw ModelError(fmt::format("{} is empty", where.describe()));
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes.front() < 0 || nodes.back() >= mesh.n_nodes()) {
    throw ModelError(fmt::format("{} refers to node {} (mesh has {} nodes)", where.describe(),
                                 nodes.front() < 0 ? nodes.front() : nodes.back(), mesh.n_nodes()));
  }
  return nodes;
}

const std::vector<ElementSide>& resolve_edge_set(const Mesh& mesh, const std::string& name) {
  const auto it = mesh.edge_sets.find(name);
  if (it == mesh.edge_sets.end()) {
    throw ModelError(fmt::format("unknown edge set '{}'", name));
  }
  if (it->second.empty()) {
    throw ModelError(fmt::format("edge set '{}' is empty", name));
  }
  for (const ElementSide& s : it->second) {
    if (s.element < 0 || s.element >= mesh.n_elements() || s.side < 0 || s.side > 3) {
      throw ModelError(
          fmt::format("edge set '{}' refers to side {} of element {} (mesh has {} "
                      "elements, sides 0..3)",
                      name, s.side, s.element, mesh.n_elements()));
    }
  }
  return it->second;
}

namespace {

void validate_mesh(const Model& model) {
  const Mesh& mesh = model.mesh;
  if (mesh.n_elements() == 0)
    throw ModelError("the mesh has no elements");
  if (mesh.body_names.empty())
    throw ModelError("the mesh has no bodies (body_names is empty)");
  if (mesh.element_body.size() != mesh.elements.size()) {
    throw ModelError(fmt::format("mesh: element_body has {} entries for {} elements",
                                 mesh.element_body.size(), mesh.elements.size()));
  }
  const int nen = mesh.n_element_nodes();
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const int b = mesh.element_body[e];
    if (b < 0 || b >= model.n_bodies()) {
      throw ModelError(
          fmt::format("element {}: body index {} (mesh has {} bodies)", e, b, model.n_bodies()));
    }
    for (int a = 0; a < nen; ++a) {
      const int n = mesh.elements[e][a];
      if (n < 0 || n >= mesh.n_nodes()) {
        throw ModelError(
            fmt::format("element {} of body '{}': local node {} is node {} (mesh "
                        "has {} nodes)",
                        e, mesh.body_names[b], a, n, mesh.n_nodes()));
      }
    }
  }
  double extent = 0.0;
  for (const auto& x : mesh.nodes) {
    if (!x.allFinite())
      throw ModelError("mesh: a node coordinate is not finite");
    extent = std::max(extent, x.cwiseAbs().maxCoeff());
  }
  if (model.analysis == AnalysisType::Axisymmetric) {
    const double tol = 1e-12 * extent;
    for (int n = 0; n < mesh.n_nodes(); ++n) {
      if (mesh.nodes[n].x() < -tol) {
        throw ModelError(
            fmt::format("axisymmetric model: node {} at r = {} < 0 (the mesh must "
                        "lie in r >= 0, axis at r = 0)",
                        n, mesh.nodes[n].x()));
      }
    }
  }
}

void check_points(int points, const std::string& what) {
  if (points < 0 || points > kMaxGaussPoints) {
    throw ModelError(fmt::format("{}: {} Gauss points requested (0 for the default, or 1 to {})",
                                 what, points, kMaxGaussPoints));
  }
}

}  // namespace

void validate(const Model& model, const LoadCase& loads) {
  for (const EdgeTraction& t : loads.tractions) {
    resolve_edge_set(model.mesh, t.edge_set);
    if (!t.traction)
      throw ModelError(fmt::format("traction on edge set '{}': no function given", t.edge_set));
    check_points(t.gauss_points, fmt::format("traction on edge set '{}'", t.edge_set));
  }
  for (const EdgePressure& p : loads.pressures) {
    resolve_edge_set(model.mesh, p.edge_set);
    if (!p.pressure)
      throw ModelError(fmt::format("pressure on edge set '{}': no function given", p.edge_set));
    check_points(p.gauss_points, fmt::format("pressure on edge set '{}'", p.edge_set));
  }
  for (const PointForce& f : loads.point_forces) {
    resolve_nodes(model.mesh, f.where);
    if (!f.force.allFinite()) {
      throw ModelError(fmt::format("point force on {} is not finite", f.where.describe()));
    }
  }
  for (const BodyForce& b : loads.body_forces) {
    if (!b.force_density)
      throw ModelError("body force: no function given");
    if (b.body < -1 || b.body >= model.n_bodies()) {
      throw ModelError(fmt::format("body force on body index {} (mesh has {} bodies; -1 = all)",
                                   b.body, model.n_bodies()));
    }
  }
}

void validate(const Model& model) {
  validate_mesh(model);
  if (static_cast<int>(model.materials.size()) != model.n_bodies()) {
    throw ModelError(
        fmt::format("{} materials given for {} bodies (one per body, indexed like "
                    "mesh.body_names)",
                    model.materials.size(), model.n_bodies()));
  }
  for (int b = 0; b < model.n_bodies(); ++b) {
    validate(model.materials[b], model.mesh.body_names[b]);
  }
  for (const PrescribedDisplacement& p : model.prescribed) {
    resolve_nodes(model.mesh, p.where);
    const int c = static_cast<int>(p.component);
    if (c != 0 && c != 1) {
      throw ModelError(fmt::format("prescribed displacement on {}: component {} (0 = x|r, 1 = z)",
                                   p.where.describe(), c));
    }
    if (!p.value) {
      throw ModelError(
          fmt::format("prescribed displacement on {}: no value given", p.where.describe()));
    }
  }
  check_points(model.quadrature.element_points, "quadrature.element_points");
  check_points(model.quadrature.body_force_points, "quadrature.body_force_points");
  check_points(model.quadrature.edge_points, "quadrature.edge_points");
  validate(model, model.loads);
}

}  // namespace cs::solver

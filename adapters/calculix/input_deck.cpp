#include "adapters/calculix/input_deck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <variant>

#include <fmt/format.h>

#include "adapters/calculix/calculix_error.hpp"
#include "solver/dof_map.hpp"
#include "solver/load_vector.hpp"
#include "solver/model_error.hpp"

namespace cs::adapters::calculix {
namespace {

using solver::Model;

/// A number in at most 20 characters (ccx reads 20 per field): 13 significant digits.
std::string num(double v) {
  if (!std::isfinite(v))
    throw CalculixError(fmt::format("CalculiX deck: value {} is not finite", v));
  return fmt::format("{:.12e}", v);
}

/// Text from the model for a comment line: [A-Za-z0-9._-] kept, anything else '_'.
std::string comment_safe(const std::string& text) {
  std::string out = text.substr(0, 60);
  for (char& c : out) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '-';
    if (!keep)
      c = '_';
  }
  return out;
}

const std::string& target_edge_set(const solver::ContactPair& pair) {
  if (const auto* surface = std::get_if<solver::TargetSurface>(&pair.target))
    return surface->edge_set;
  throw UnsupportedByCalculix(
      "CalculiX: a rigid analytic target is not supported (the adapter writes meshed "
      "surfaces only; use the discretized indenter)");
}

const std::vector<solver::ElementSide>& checked_edge_set(const Model& model,
                                                         const std::string& name,
                                                         const char* role) {
  try {
    return solver::resolve_edge_set(model.mesh, name);
  } catch (const solver::ModelError& e) {
    throw CalculixError(fmt::format("CalculiX deck: {} '{}': {}", role, name, e.what()));
  }
}

/// Which nodes lie on the axis: |r| within round-off (1e-12) of the mesh's extent. A node
/// placed by trigonometry, e.g. r = R cos(pi / 2) = 6e-17 R at the pole of a sphere, is on the
/// axis as much as one at r = 0, and its faces collapse alike in CalculiX's expansion.
std::vector<char> nodes_on_axis(const solver::Mesh& mesh) {
  double extent = 0.0;
  for (const auto& x : mesh.nodes)
    extent = std::max(extent, x.cwiseAbs().maxCoeff());
  std::vector<char> on_axis(mesh.nodes.size(), 0);
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    on_axis[n] = std::abs(mesh.nodes[n].x()) <= 1e-12 * extent;
  return on_axis;
}

/// The r written for nodes on the axis: axis_offset x the shortest side touching the axis.
double axis_radius(const Model& model, const CalculixOptions& options,
                   const std::vector<char>& on_axis) {
  const auto& mesh = model.mesh;
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& element : mesh.elements) {
    for (int s = 0; s < 4; ++s) {
      const int a = element[s], b = element[(s + 1) % 4];
      if (on_axis[a] || on_axis[b])
        shortest = std::min(shortest, (mesh.nodes[a] - mesh.nodes[b]).norm());
    }
  }
  return std::isfinite(shortest) ? options.axis_offset * shortest : 0.0;
}

void write_nodes(std::ostream& out, const Model& model, const CalculixOptions& options) {
  const bool axisymmetric = model.analysis == solver::AnalysisType::Axisymmetric;
  const std::vector<char> on_axis =
      axisymmetric ? nodes_on_axis(model.mesh) : std::vector<char>(model.mesh.nodes.size(), 0);
  const double r_axis = axisymmetric ? axis_radius(model, options, on_axis) : 0.0;
  if (r_axis > 0.0)
    out << "** nodes on the axis are written at r = " << num(r_axis) << " (see axis_offset)\n";
  out << "*NODE, NSET=NALL\n";
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const auto& x = model.mesh.nodes[n];
    const double r = axisymmetric && on_axis[n] ? r_axis : x.x();
    out << ccx_node_id(n) << ", " << num(r) << ", " << num(x.y()) << "\n";
  }
}

void write_elements(std::ostream& out, const Model& model) {
  const auto& mesh = model.mesh;
  const std::string type = ccx_element_type(model);
  for (int body = 0; body < model.n_bodies(); ++body) {
    out << "** body " << body << ": " << comment_safe(mesh.body_names[body]) << "\n";
    out << "*ELEMENT, TYPE=" << type << ", ELSET=BODY" << body + 1 << "\n";
    for (int e = 0; e < mesh.n_elements(); ++e) {
      if (mesh.element_body[e] != body)
        continue;
      out << ccx_element_id(e);
      for (int k = 0; k < mesh.n_element_nodes(); ++k)
        out << ", " << ccx_node_id(mesh.elements[e][k]);
      out << "\n";
    }
  }
}

void write_materials(std::ostream& out, const Model& model) {
  const bool axisymmetric = model.analysis == solver::AnalysisType::Axisymmetric;
  for (int body = 0; body < model.n_bodies(); ++body) {
    const auto& m = model.materials[body];
    out << "*MATERIAL, NAME=MAT" << body + 1 << "\n*ELASTIC\n"
        << num(m.youngs_modulus_E) << ", " << num(m.poissons_ratio_nu) << "\n";
    out << "*SOLID SECTION, ELSET=BODY" << body + 1 << ", MATERIAL=MAT" << body + 1 << "\n";
    if (!axisymmetric)
      out << "1.0\n";  // plane strain: unit thickness, so forces are per unit thickness
  }
}

void write_surface(std::ostream& out, const std::string& name,
                   const std::vector<solver::ElementSide>& sides) {
  out << "*SURFACE, NAME=" << name << "\n";
  for (const auto& s : sides)
    out << ccx_element_id(s.element) << ", " << ccx_face_label(s.side) << "\n";
}

void write_interaction(std::ostream& out, const CalculixOptions& options) {
  out << "*SURFACE INTERACTION, NAME=CONTACT\n";
  out << "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=" << to_string(options.behavior) << "\n";
  const bool ns = options.contact == CcxContactType::NodeToSurface;
  if (options.behavior == CcxPressureOverclosure::Linear) {
    out << num(options.penalty_K);
    if (ns)
      out << ", " << num(options.tension_sigma_inf) << ", " << num(options.spring_distance_c0);
    out << "\n";
  } else if (ns) {
    // HARD is LINEAR with ccx's defaults where a value is 0: keep K and sigma_inf, set c0.
    out << "0, 0, " << num(options.spring_distance_c0) << "\n";
  }
  out << "*CONTACT PAIR, INTERACTION=CONTACT, TYPE=" << to_string(options.contact);
  if (options.contact == CcxContactType::NodeToSurface && options.small_sliding)
    out << ", SMALL SLIDING";
  out << "\nSLAVE, MASTER\n";
}

void write_boundary(std::ostream& out, const solver::DofMap& dofs) {
  out << "*BOUNDARY\n";
  for (int dof : dofs.constrained_dofs()) {
    const int direction = dof % 2 + 1;  // 1: x|r, 2: our z (CalculiX's y)
    out << ccx_node_id(dof / 2) << ", " << direction << ", " << direction << ", "
        << num(dofs.prescribed_values()[dof]) << "\n";
  }
}

void write_loads(std::ostream& out, const Model& model, const solver::DofMap& dofs) {
  const Eigen::VectorXd f = solver::assemble_load_vector(model, model.loads);
  const double factor = ccx_force_factor(model);
  // Round-off of the edge quadrature (e.g. 1e-16 x-components of a pressure on a z face).
  const double negligible = 1e-13 * (f.size() > 0 ? f.cwiseAbs().maxCoeff() : 0.0);
  out << "*CLOAD\n";
  for (int dof = 0; dof < f.size(); ++dof) {
    if (std::abs(f[dof]) > negligible && dofs.is_free(dof))
      out << ccx_node_id(dof / 2) << ", " << dof % 2 + 1 << ", " << num(factor * f[dof]) << "\n";
  }
}

void write_step(std::ostream& out, const Model& model, const solver::DofMap& dofs) {
  out << "*STEP\n*STATIC\n1.0, 1.0\n";
  write_loads(out, model, dofs);
  out << "*NODE FILE\nU, RF\n*EL FILE\nS\n*CONTACT FILE\nCDIS, CSTR\n*END STEP\n";
}

}  // namespace

std::string ccx_face_label(int side) {
  if (side < 0 || side > 3)
    throw CalculixError(fmt::format("CalculiX deck: element side {} is not 0..3", side));
  return fmt::format("S{}", side + 1);
}

std::string ccx_element_type(const Model& model) {
  const bool q8 = model.mesh.type == solver::ElementType::Q8;
  if (model.analysis == solver::AnalysisType::Axisymmetric)
    return q8 ? "CAX8" : "CAX4";
  return q8 ? "CPE8" : "CPE4";
}

double ccx_force_factor(const Model& model) {
  return model.analysis == solver::AnalysisType::Axisymmetric ? 2.0 * std::numbers::pi : 1.0;
}

void write_input_deck(std::ostream& out, const Model& model, const solver::ContactPair& pair,
                      const CalculixOptions& options) {
  solver::validate(model);
  validate(options);
  const auto& master = checked_edge_set(model, target_edge_set(pair), "target surface");
  const auto& slave = checked_edge_set(model, pair.contact_surface, "contact surface");
  const solver::DofMap dofs(model);
  out << "** contact-suite: " << solver::to_string(model.analysis) << ", " << model.mesh.n_nodes()
      << " nodes, " << model.mesh.n_elements() << " elements\n";
  out << "** slave: " << comment_safe(pair.contact_surface)
      << ", master: " << comment_safe(target_edge_set(pair)) << "\n";
  write_nodes(out, model, options);
  write_elements(out, model);
  write_materials(out, model);
  write_surface(out, "SLAVE", slave);
  write_surface(out, "MASTER", master);
  write_interaction(out, options);
  write_boundary(out, dofs);
  write_step(out, model, dofs);
}

std::string input_deck(const Model& model, const solver::ContactPair& pair,
                       const CalculixOptions& options) {
  std::ostringstream out;
  write_input_deck(out, model, pair, options);
  return out.str();
}

}  // namespace cs::adapters::calculix

#include "suites/case_directory.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "solver/dof_map.hpp"
#include "solver/load_vector.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "suites/model_export.hpp"

namespace cs::suites {
namespace {

using nlohmann::json;

json point(const Eigen::Vector2d& x) {
  return json::array({x.x(), x.y()});
}

// ---- mesh.msh -------------------------------------------------------------------------------

/// Gmsh element types: 3 = 4-node quadrangle, 16 = 8-node quadrangle, 1 = 2-node line,
/// 8 = 3-node line, 15 = point.
int gmsh_quad_type(const solver::Mesh& mesh) {
  return mesh.type == solver::ElementType::Q8 ? 16 : 3;
}
int gmsh_line_type(const solver::Mesh& mesh) {
  return mesh.type == solver::ElementType::Q8 ? 8 : 1;
}

/// The node sets written as point groups (dimension 0), by their group name: a node set that
/// is exactly the nodes of the edge set of its name is not repeated (readers such as meshio
/// key groups by name alone); one that differs from it is called "<name>:nodes".
std::vector<std::pair<std::string, const std::vector<int>*>> point_groups(
    const solver::Mesh& mesh) {
  std::vector<std::pair<std::string, const std::vector<int>*>> out;
  for (const auto& [name, nodes] : mesh.node_sets) {
    const auto edges = mesh.edge_sets.find(name);
    if (edges == mesh.edge_sets.end()) {
      out.emplace_back(name, &nodes);
      continue;
    }
    std::vector<int> a = nodes, b = solver::nodes_of_sides(mesh, edges->second);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    if (a != b)
      out.emplace_back(name + ":nodes", &nodes);
  }
  return out;
}

/// Physical groups: the bodies (dimension 2), the edge sets (1), the node sets (0,
/// point_groups); each set is one entity of its dimension whose tag is its physical tag.
std::string physical_names(const solver::Mesh& mesh) {
  const auto points = point_groups(mesh);
  const std::size_t n = mesh.body_names.size() + mesh.edge_sets.size() + points.size();
  std::string out = fmt::format("$PhysicalNames\n{}\n", n);
  int tag = 0;
  for (const auto& group : points)
    out += fmt::format("0 {} \"{}\"\n", ++tag, group.first);
  tag = 0;
  for (const auto& name : mesh.edge_sets)
    out += fmt::format("1 {} \"{}\"\n", ++tag, name.first);
  tag = 0;
  for (const auto& name : mesh.body_names)
    out += fmt::format("2 {} \"{}\"\n", ++tag, name);
  return out + "$EndPhysicalNames\n";
}

/// The entities carry no geometry beyond a bounding box (the mesh's): points at the origin.
std::string entities(const solver::Mesh& mesh) {
  const std::size_t n_points = point_groups(mesh).size();
  std::string out = fmt::format("$Entities\n{} {} {} 0\n", n_points, mesh.edge_sets.size(),
                                mesh.body_names.size());
  Eigen::Vector2d lo = mesh.nodes.front(), hi = mesh.nodes.front();
  for (const auto& x : mesh.nodes)
    lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const std::string box =
      fmt::format("{} {} 0 {} {} 0", round_trip_text(lo.x()), round_trip_text(lo.y()),
                  round_trip_text(hi.x()), round_trip_text(hi.y()));
  for (std::size_t t = 1; t <= n_points; ++t)
    out += fmt::format("{} 0 0 0 1 {}\n", t, t);
  for (std::size_t t = 1; t <= mesh.edge_sets.size(); ++t)
    out += fmt::format("{} {} 1 {} 0\n", t, box, t);
  for (std::size_t t = 1; t <= mesh.body_names.size(); ++t)
    out += fmt::format("{} {} 1 {} 0\n", t, box, t);
  return out + "$EndEntities\n";
}

/// Every node in one block of the first body's surface entity (tags are the node ids).
std::string nodes_section(const solver::Mesh& mesh) {
  const int n = mesh.n_nodes();
  std::string out = fmt::format("$Nodes\n1 {} 1 {}\n2 1 0 {}\n", n, n, n);
  for (int i = 1; i <= n; ++i)
    out += fmt::format("{}\n", i);
  for (const auto& x : mesh.nodes)
    out += fmt::format("{} {} 0\n", round_trip_text(x.x()), round_trip_text(x.y()));
  return out + "$EndNodes\n";
}

std::string elements_section(const solver::Mesh& mesh) {
  std::string blocks;
  int n_blocks = 0, n_elements = 0, tag = mesh.n_elements();
  int entity = 0;
  for (const auto& [name, nodes] : point_groups(mesh)) {
    blocks += fmt::format("0 {} 15 {}\n", ++entity, nodes->size());
    for (int node : *nodes)
      blocks += fmt::format("{} {}\n", ++tag, node + 1);
    ++n_blocks, n_elements += static_cast<int>(nodes->size());
  }
  entity = 0;
  for (const auto& [name, sides] : mesh.edge_sets) {
    blocks += fmt::format("1 {} {} {}\n", ++entity, gmsh_line_type(mesh), sides.size());
    for (const auto& s : sides) {
      const auto n = mesh.side_nodes(s);  // Gmsh's 3-node line: both ends, then the middle
      blocks += fmt::format("{} {} {}", ++tag, n[0] + 1, n[1] + 1);
      blocks += n[2] >= 0 ? fmt::format(" {}\n", n[2] + 1) : "\n";
    }
    ++n_blocks, n_elements += static_cast<int>(sides.size());
  }
  for (int b = 0; b < static_cast<int>(mesh.body_names.size()); ++b) {
    std::string rows;
    int count = 0;
    for (int e = 0; e < mesh.n_elements(); ++e) {
      if (mesh.element_body[e] != b)
        continue;
      rows += fmt::format("{}", e + 1);
      for (int k = 0; k < mesh.n_element_nodes(); ++k)
        rows += fmt::format(" {}", mesh.elements[e][k] + 1);
      rows += '\n';
      ++count;
    }
    blocks += fmt::format("2 {} {} {}\n", b + 1, gmsh_quad_type(mesh), count) + rows;
    ++n_blocks, n_elements += count;
  }
  return fmt::format("$Elements\n{} {} 1 {}\n", n_blocks, n_elements, tag) + blocks +
         "$EndElements\n";
}

// ---- case.json ------------------------------------------------------------------------------

json signed_distance(const solver::RigidProfile& profile) {
  return std::visit(
      [](const auto& p) -> json {
        using T = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<T, solver::RigidPlane>) {
          return {{"type", "plane"},
                  {"point", point(p.point)},
                  {"normal", point(p.normal.normalized())},
                  {"signed_distance", "g(x) = (x - point) . normal"}};
        } else if constexpr (std::is_same_v<T, solver::RigidCircle>) {
          return {{"type", "circle"},
                  {"center", point(p.center)},
                  {"radius", p.radius},
                  {"signed_distance", "g(x) = |x - center| - radius"}};
        } else if constexpr (std::is_same_v<T, solver::RoundedFlatPunch>) {
          return {{"type", "rounded_flat_punch"},
                  {"face_center", point(p.face_center)},
                  {"direction", point(p.direction.normalized())},
                  {"half_width_b", p.half_width_b},
                  {"edge_radius_re", p.edge_radius_re},
                  {"signed_distance",
                   "h = (x - face_center) . d, s = |(x - face_center) . t|, t = (d_z, -d_x); "
                   "g = h if s <= b; g = hypot(s - b, h + r_e) - r_e if s > b and h >= -r_e; "
                   "g = s - b - r_e otherwise"}};
        } else {
          return {{"type", "sharp_flat_punch"},
                  {"face_center", point(p.face_center)},
                  {"direction", point(p.direction.normalized())},
                  {"half_width_a", p.half_width_a},
                  {"signed_distance",
                   "h = (x - face_center) . d, s = |(x - face_center) . t|, t = (d_z, -d_x); "
                   "g = h if s <= a; g = hypot(s - a, h) if s > a and h >= 0; g = s - a "
                   "otherwise"}};
        }
      },
      profile);
}

json contact_pair_json(const ProblemSetup& setup) {
  const solver::ContactPair& pair = setup.pair;
  json target;
  if (const auto* surface = std::get_if<solver::TargetSurface>(&pair.target)) {
    target = {{"kind", "meshed"}, {"surface", surface->edge_set}};
  } else {
    target = {{"kind", "rigid"},
              {"profile", signed_distance(std::get<solver::RigidProfile>(pair.target))}};
  }
  return {
      {"contact_surface", pair.contact_surface},
      {"target", target},
      {"gap_normal", pair.gap_normal == solver::GapNormal::Target ? "target" : "contact_surface"},
      {"frictionless", true}};
}

/// The body a rigid target's mesh belongs to is fixed and takes no part in the contact.
json bodies_json(const ProblemSetup& setup) {
  const solver::Model& model = setup.model;
  const bool rigid = std::holds_alternative<solver::RigidProfile>(setup.pair.target);
  json out = json::array();
  for (int b = 0; b < model.n_bodies(); ++b) {
    const bool passive = rigid && b != 0;
    out.push_back({{"name", model.mesh.body_names[b]},
                   {"physical_group", model.mesh.body_names[b]},
                   {"role", passive ? "fixed_not_in_contact" : "deformable"},
                   {"E", model.materials[b].youngs_modulus_E},
                   {"nu", model.materials[b].poissons_ratio_nu}});
  }
  return out;
}

bool is_load_controlled(const ProblemSetup& setup, const solver::PrescribedDisplacement& c) {
  return setup.load_control && c.component == solver::Component::Z &&
         c.where.name == setup.load_control->reaction_set;
}

/// One entry per prescribed displacement: the set, the component and either one value (the
/// same at every node), per-node values, or "load_controlled" (the unknown of the load control).
json boundary_json(const ProblemSetup& setup) {
  const solver::Model& model = setup.model;
  json out = json::array();
  for (const auto& c : model.prescribed) {
    const auto nodes = solver::resolve_nodes(model.mesh, c.where);
    json entry = {{"set", c.where.name},
                  {"set_kind",
                   c.where.kind == solver::NodeSelection::Kind::EdgeSet ? "edge_set" : "node_set"},
                  {"component", c.component == solver::Component::X ? "x" : "z"}};
    if (is_load_controlled(setup, c)) {
      entry["load_controlled"] = true;
    } else {
      json values = json::array();
      bool uniform = true;
      const double first = c.value(model.mesh.nodes[nodes.front()]);
      for (int n : nodes) {
        const double v = c.value(model.mesh.nodes[n]);
        uniform = uniform && v == first;
        values.push_back(json::array({n + 1, v}));
      }
      if (uniform)
        entry["value"] = first;
      else
        entry["values"] = values;
    }
    out.push_back(entry);
  }
  return out;
}

/// The consistent nodal forces the built-in solver applies at free DOFs.
json loads_json(const solver::Model& model) {
  const Eigen::VectorXd f = solver::assemble_load_vector(model, model.loads);
  const solver::DofMap dofs(model);
  json forces = json::array();
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const double fx = dofs.is_free(2 * n) ? f[2 * n] : 0.0;
    const double fz = dofs.is_free(2 * n + 1) ? f[2 * n + 1] : 0.0;
    if (fx != 0.0 || fz != 0.0)
      forces.push_back(json::array({n + 1, fx, fz}));
  }
  return {{"nodal_forces", forces},
          {"columns", json::array({"node_id", "fx", "fz"})},
          {"note", "consistent nodal forces of the problem's tractions and pressures"}};
}

json load_control_json(const ProblemSetup& setup) {
  if (!setup.load_control)
    return {{"kind", "given_loads"},
            {"note", "the loads and prescribed displacements are given; nothing is unknown"}};
  const RigidLoadControl& c = *setup.load_control;
  return {{"kind", "total_load"},
          {"total_load", c.target_load},
          {"component", "z"},
          {"reaction_set", c.reaction_set},
          {"depth_guess", c.delta_guess},
          {"note",
           "the depth is unknown: every node of reaction_set has u_z = -delta (it advances "
           "towards the rigid target, which stays put), one unknown delta such that the z "
           "reaction on reaction_set equals total_load"}};
}

json sampled_json(const ProblemSetup& setup) {
  json quantities = json::array();
  for (const QuantityRule& rule : setup.quantities) {
    quantities.push_back(
        {{"quantity", schema::to_string(rule.quantity)},
         {"component", stress_component_name(rule.component)},
         {"rule", sample_rule_name(rule.where)},
         {"exact", std::isfinite(rule.exact) ? json(rule.exact) : json("inf")},
         {"study_exact", rule.study_exact ? json(*rule.study_exact) : json(nullptr)}});
  }
  return {{"surface", kSampledSurface}, {"quantities", quantities}};
}

json results_json() {
  return {{"displacements", "displacements.csv"},
          {"stresses", "stresses.csv"},
          {"contact_pressure", "contact_pressure.csv"},
          {"status", "status.json"}};
}

}  // namespace

std::string gmsh_document(const solver::Model& model) {
  const solver::Mesh& mesh = model.mesh;
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + physical_names(mesh) + entities(mesh) +
         nodes_section(mesh) + elements_section(mesh);
}

std::string case_json(const CaseSpec& spec, const ProblemSetup& setup, const std::string& option) {
  const solver::Model& model = setup.model;
  const bool axi = model.analysis == solver::AnalysisType::Axisymmetric;
  json j;
  j["format"] = "contact-suite case";
  j["format_version"] = kCaseFormatVersion;
  j["case_id"] = case_id(spec);
  j["problem"] = to_string(spec.problem);
  j["mesh_level"] = to_string(spec.mesh);
  j["option"] = option;
  j["analysis"] = axi ? "axisymmetric" : "plane_strain";
  j["force_basis"] = axi ? "per_radian" : "per_unit_thickness";
  j["coordinates"] = "(x, z) in mesh.msh's (x, y); z points into the indented body";
  j["mesh"] = {{"file", "mesh.msh"},
               {"element", to_string(spec.element)},
               {"n_nodes", model.mesh.n_nodes()},
               {"n_elements", model.mesh.n_elements()},
               {"node_sets", json::array()},
               {"edge_sets", json::array()}};
  for (const auto& group : point_groups(model.mesh))
    j["mesh"]["node_sets"].push_back(group.first);
  for (const auto& s : model.mesh.edge_sets)
    j["mesh"]["edge_sets"].push_back(s.first);
  j["scales"] = {{"p", setup.p},
                 {"length_unit", setup.length_unit},
                 {"contact_half_width_a", setup.contact_half_width_a}};
  j["bodies"] = bodies_json(setup);
  j["boundary_conditions"] = boundary_json(setup);
  j["loads"] = loads_json(model);
  j["contact_pair"] = contact_pair_json(setup);
  j["load_control"] = load_control_json(setup);
  j["sampled"] = sampled_json(setup);
  j["results"] = results_json();
  return j.dump(1) + "\n";
}

void write_case_directory(const std::filesystem::path& dir, const CaseSpec& spec,
                          const ProblemSetup& setup, const std::string& option) {
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream out(dir / name, std::ios::binary);
    out << text;
    out.close();
    if (!out)
      throw std::runtime_error("cannot write " + (dir / name).string());
  };
  write("mesh.msh", gmsh_document(setup.model));
  write("case.json", case_json(spec, setup, option));
}

}  // namespace cs::suites

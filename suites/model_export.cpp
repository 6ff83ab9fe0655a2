#include "suites/model_export.hpp"

#include <cmath>
#include <numeric>
#include <variant>

#include <fmt/format.h>

#include "solver/dof_map.hpp"
#include "solver/io/vtu_writer.hpp"
#include "solver/load_vector.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/runner.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

std::string direction(int component) {
  return component == 0 ? "x" : "y";
}

const std::string& target_surface(const solver::ContactPair& pair) {
  static const std::string none;
  const auto* surface = std::get_if<solver::TargetSurface>(&pair.target);
  return surface ? surface->edge_set : none;
}

std::string model_csv(const ProblemSetup& setup) {
  const solver::Model& m = setup.model;
  const bool axi = m.analysis == solver::AnalysisType::Axisymmetric;
  std::string out = "key,value\n";
  out += fmt::format("analysis,{}\n", axi ? "axisymmetric" : "plane_strain");
  out += fmt::format("element_type,{}\n", m.mesh.type == solver::ElementType::Q8 ? "Q8" : "Q4");
  out += fmt::format("n_nodes,{}\nn_elements,{}\n", m.mesh.n_nodes(), m.mesh.n_elements());
  out += fmt::format("thickness,{}\n", axi ? "" : "1");
  out += fmt::format("force_basis,{}\n", axi ? "per_radian" : "per_unit_thickness");
  out +=
      fmt::format("p,{}\nlength_unit,{}\ncontact_half_width_a,{}\n", round_trip_text(setup.p),
                  round_trip_text(setup.length_unit), round_trip_text(setup.contact_half_width_a));
  out += fmt::format("contact_surface,{}\ntarget_surface,{}\nsampled_surface,{}\n",
                     setup.pair.contact_surface, target_surface(setup.pair), kSampledSurface);
  return out;
}

std::string nodes_csv(const solver::Mesh& mesh) {
  std::string out = "id,x,y\n";
  for (int n = 0; n < mesh.n_nodes(); ++n)
    out += fmt::format("{},{},{}\n", n + 1, round_trip_text(mesh.nodes[n].x()),
                       round_trip_text(mesh.nodes[n].y()));
  return out;
}

std::string elements_csv(const solver::Mesh& mesh) {
  std::string out = "id,type,body,n1,n2,n3,n4,n5,n6,n7,n8\n";
  const bool q8 = mesh.type == solver::ElementType::Q8;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    out += fmt::format("{},{},{}", e + 1, q8 ? "Q8" : "Q4", mesh.element_body[e]);
    for (int k = 0; k < 8; ++k)
      out += k < mesh.n_element_nodes() ? fmt::format(",{}", mesh.elements[e][k] + 1) : ",";
    out += '\n';
  }
  return out;
}

/// Every node set of the mesh (kind "nodes") and the nodes of every edge set ("surface").
std::string node_sets_csv(const solver::Mesh& mesh) {
  std::string out = "set,kind,node_id\n";
  for (const auto& [name, nodes] : mesh.node_sets) {
    for (int n : nodes)
      out += fmt::format("{},nodes,{}\n", name, n + 1);
  }
  for (const auto& [name, sides] : mesh.edge_sets) {
    for (int n : solver::nodes_of_sides(mesh, sides))
      out += fmt::format("{},surface,{}\n", name, n + 1);
  }
  return out;
}

/// Every edge set as element faces: face k+1 runs from corner k to corner k+1 (CalculiX's Sk).
std::string surfaces_csv(const solver::Mesh& mesh) {
  std::string out = "surface,element_id,face,node_a,node_b,node_mid\n";
  for (const auto& [name, sides] : mesh.edge_sets) {
    for (const auto& s : sides) {
      const auto n = mesh.side_nodes(s);
      out += fmt::format("{},{},{},{},{},{}\n", name, s.element + 1, s.side + 1, n[0] + 1, n[1] + 1,
                         n[2] >= 0 ? std::to_string(n[2] + 1) : "");
    }
  }
  return out;
}

/// Every prescribed displacement, one row per node and direction, evaluated at the node.
std::string boundary_csv(const solver::Model& model) {
  std::string out = "constraint,node_id,direction,value\n";
  for (const auto& c : model.prescribed) {
    for (int n : solver::resolve_nodes(model.mesh, c.where)) {
      const int component = c.component == solver::Component::X ? 0 : 1;
      out += fmt::format("{},{},{},{}\n", c.where.name, n + 1, direction(component),
                         round_trip_text(c.value(model.mesh.nodes[n])));
    }
  }
  return out;
}

/// The consistent nodal forces the solver applies: every node with a non-zero force at a free
/// DOF (a component at a prescribed DOF is written 0: it goes to the reaction).
std::string loads_csv(const solver::Model& model) {
  const Eigen::VectorXd f = solver::assemble_load_vector(model, model.loads);
  const solver::DofMap dofs(model);
  std::string out = "node_id,fx,fy\n";
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const double fx = dofs.is_free(2 * n) ? f[2 * n] : 0.0;
    const double fy = dofs.is_free(2 * n + 1) ? f[2 * n + 1] : 0.0;
    if (fx != 0.0 || fy != 0.0)
      out += fmt::format("{},{},{}\n", n + 1, round_trip_text(fx), round_trip_text(fy));
  }
  return out;
}

std::string materials_csv(const solver::Model& model) {
  std::string out = "body,name,E,nu\n";
  for (int b = 0; b < model.n_bodies(); ++b) {
    out += fmt::format("{},{},{},{}\n", b, model.mesh.body_names[b],
                       round_trip_text(model.materials[b].youngs_modulus_E),
                       round_trip_text(model.materials[b].poissons_ratio_nu));
  }
  return out;
}

std::string contact_pair_csv(const solver::ContactPair& pair) {
  return fmt::format("role,surface\ncontact,{}\ntarget,{}\n", pair.contact_surface,
                     target_surface(pair));
}

}  // namespace

std::string round_trip_text(double v) {
  return fmt::format("{:.17g}", v);
}

std::string_view sample_rule_name(SamplePoint where) {
  switch (where) {
    case SamplePoint::MaxOnSurface:
      return "max_on_surface";
    case SamplePoint::AtAxis:
      return "at_axis";
    case SamplePoint::AtEdge:
      return "at_edge";
    case SamplePoint::StickZoneEdge:
      return "stick_zone_edge";
    case SamplePoint::ContactPeakShear:
      return "contact_peak_shear";
    case SamplePoint::ContactEdge:
      return "contact_edge";
    case SamplePoint::InterfaceMeanPressure:
      return "interface_mean_pressure";
    case SamplePoint::ArcPressureExtreme:
      return "arc_pressure_extreme";
  }
  return "";
}

std::string_view stress_component_name(StressComponent c) {
  switch (c) {
    case StressComponent::SigmaZ:
      return "sigma_z";
    case StressComponent::SigmaX:
      return "sigma_x";
    case StressComponent::TauXZ:
      return "tau_xz";
  }
  return "";
}

void require_exchangeable(const CaseSpec& spec) {
  if (spec.target == TargetKind::Rigid)
    throw SuiteInputError(fmt::format(
        "{}: a rigid target is not in the export layout (meshed targets only: use --target "
        "discretized, or the solver protocol's case directory, docs/solver-protocol.md)",
        case_id(spec)));
  require_importable(spec);
}

void require_importable(const CaseSpec& spec) {
  if (is_frictional(spec.problem))
    throw SuiteInputError(fmt::format(
        "{}: {} has friction, which the import/export layout does not carry (no load path, "
        "shear stress or stick/slip states)",
        case_id(spec), to_string(spec.problem)));
  if (problem_descriptor(spec.problem).situation == schema::Situation::conformal_fit)
    throw SuiteInputError(fmt::format(
        "{}: {} is graded from the contact's nodal forces along the arc, which the import/export "
        "layout does not carry",
        case_id(spec), to_string(spec.problem)));
}

std::string model_directory_name(const CaseSpec& spec) {
  // model_key is "P/M/E/<algorithm>/<contact>[/options]": keep all but the two contact fields.
  const std::string key = model_key(spec);
  std::string name;
  std::size_t start = 0;
  for (int field = 0; start <= key.size(); ++field) {
    const auto slash = std::min(key.find('/', start), key.size());
    if (field != 3 && field != 4) {
      if (!name.empty())
        name += '_';
      name.append(key, start, slash - start);
    }
    start = slash + 1;
  }
  return plain_file_name(name);
}

std::vector<ExportFile> model_files(const ProblemSetup& setup) {
  const solver::Model& model = setup.model;
  std::vector<double> ids(static_cast<std::size_t>(model.mesh.n_nodes()));
  std::iota(ids.begin(), ids.end(), 1.0);
  return {{"model.csv", model_csv(setup)},
          {"nodes.csv", nodes_csv(model.mesh)},
          {"elements.csv", elements_csv(model.mesh)},
          {"node_sets.csv", node_sets_csv(model.mesh)},
          {"surfaces.csv", surfaces_csv(model.mesh)},
          {"boundary.csv", boundary_csv(model)},
          {"loads.csv", loads_csv(model)},
          {"materials.csv", materials_csv(model)},
          {"contact_pair.csv", contact_pair_csv(setup.pair)},
          {"mesh.vtu", solver::vtu_document(model.mesh, {{"node_id", 1, ids, true}})}};
}

std::string cases_csv_header() {
  return "case_id,model,problem,mesh,element,algorithm,contact,recovery,overrides,quantity,"
         "component,rule,exact,study_exact\n";
}

std::string cases_csv_rows(const CaseSpec& spec, const ProblemSetup& setup,
                           const std::string& model_dir) {
  std::string overrides;
  for (const auto& [name, value] : spec.overrides)
    overrides += fmt::format("{}{}={}", overrides.empty() ? "" : ";", name, value);
  const std::string options =
      fmt::format("{},{},{},{},{},{},{},{},{}", case_id(spec), model_dir, to_string(spec.problem),
                  to_string(spec.mesh), to_string(spec.element), to_string(spec.algorithm),
                  to_string(spec.contact), to_string(spec.recovery), overrides);
  std::string out;
  for (const QuantityRule& rule : setup.quantities) {
    out += fmt::format("{},{},{},{},{},{}\n", options, schema::to_string(rule.quantity),
                       stress_component_name(rule.component), sample_rule_name(rule.where),
                       std::isfinite(rule.exact) ? round_trip_text(rule.exact) : "inf",
                       rule.study_exact ? round_trip_text(*rule.study_exact) : "");
  }
  return out;
}

}  // namespace cs::suites

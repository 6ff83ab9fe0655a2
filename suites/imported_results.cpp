#include "suites/imported_results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "schema/schema_error.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/model.hpp"
#include "solver/surface_path.hpp"
#include "suites/model_export.hpp"
#include "suites/runner.hpp"
#include "suites/suite_error.hpp"
#include "suites/surface_sampling.hpp"

namespace cs::suites {
namespace {

/// A message with every byte outside printable ASCII as '?' (ids come from a file).
std::string printable(std::string text) {
  for (char& c : text) {
    if (c < 0x20 || c >= 0x7f)
      c = '?';
  }
  return text;
}

[[noreturn]] void fail_at(std::string_view source, int line, const std::string& what) {
  throw SuiteInputError(printable(fmt::format("{}:{}: {}", source, line, what)));
}

/// The sampled surface's nodes and how far a row's x may be from its node.
struct SurfaceNodes {
  solver::SurfacePath path;
  double tolerance = 0.0;  ///< 1e-3 of the smallest spacing of the nodes' x
};

SurfaceNodes surface_nodes(const ProblemSetup& setup) {
  SurfaceNodes out{solver::surface_path(setup.model.mesh, kSampledSurface), 0.0};
  std::vector<double> x;
  for (const auto& p : out.path.positions)
    x.push_back(p.x());
  std::sort(x.begin(), x.end());
  double spacing = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < x.size(); ++i)
    spacing = std::min(spacing, x[i] - x[i - 1]);
  out.tolerance = std::isfinite(spacing) ? 1e-3 * spacing : 1e-9 * setup.length_unit;
  return out;
}

/// For each node of the surface path, the index of its row in `imported` (one to one).
std::vector<std::size_t> match_rows(const SurfaceNodes& surface, const ImportedCase& imported,
                                    std::string_view source) {
  constexpr auto kNone = std::numeric_limits<std::size_t>::max();
  const auto& positions = surface.path.positions;
  std::vector<std::size_t> row_of(positions.size(), kNone);
  for (std::size_t r = 0; r < imported.rows.size(); ++r) {
    const ImportRow& row = imported.rows[r];
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < positions.size(); ++i) {
      if (std::abs(positions[i].x() - row.x) < std::abs(positions[nearest].x() - row.x))
        nearest = i;
    }
    const double node_x = positions[nearest].x();
    if (std::abs(node_x - row.x) > surface.tolerance)
      fail_at(source, row.line,
              fmt::format("case '{}': x = {} is no node of the sampled surface (nearest: x = {})",
                          imported.case_id, row.x, node_x));
    if (row_of[nearest] != kNone)
      fail_at(source, row.line,
              fmt::format("case '{}': x = {} is the node at x = {} again (line {})",
                          imported.case_id, row.x, node_x, imported.rows[row_of[nearest]].line));
    row_of[nearest] = r;
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (row_of[i] == kNone)
      fail_at(
          source, imported.line,
          fmt::format("case '{}': no row for the surface node at x = {} ({} of {} nodes given)",
                      imported.case_id, positions[i].x(), imported.rows.size(), positions.size()));
  }
  return row_of;
}

/// `basis` onto `spec`: a target or recovery the id does not state is the command line's; one
/// the id states otherwise is an error.
void apply_basis(CaseSpec& spec, const ImportBasis& basis, const ImportedCase& imported,
                 std::string_view source) {
  if (basis.target) {
    if (spec.target == TargetKind::Rigid && *basis.target != TargetKind::Rigid)
      fail_at(source, imported.line,
              fmt::format("case '{}' names a rigid target, --target {}", imported.case_id,
                          to_string(*basis.target)));
    spec.target = *basis.target;
  }
  if (basis.recovery) {
    if (spec.recovery != Recovery::spr && spec.recovery != *basis.recovery)
      fail_at(source, imported.line,
              fmt::format("case '{}' names the stress basis {}, --recovery {}", imported.case_id,
                          to_string(spec.recovery), to_string(*basis.recovery)));
    spec.recovery = *basis.recovery;
  }
}

}  // namespace

void require_imported_solver_name(std::string_view name,
                                  const std::vector<std::string>& registered) {
  const bool plain = std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' ||
           c == '_' || c == '-';
  });
  if (name.empty() || name.size() > 64 || !plain)
    throw SuiteInputError(printable(
        fmt::format("--solver-name '{}': expected 1 to 64 characters of [A-Za-z0-9._-]", name)));
  const auto is_name = [&](std::string_view taken) { return name == taken; };
  const bool taken =
      std::ranges::any_of(values<SolverKind>(),
                          [&](SolverKind kind) { return is_name(to_string(kind)); }) ||
      std::ranges::any_of(registered, is_name);
  if (taken)
    throw SuiteInputError(fmt::format(
        "--solver-name {}: the name of a solver of this suite; name the code that produced "
        "the results (e.g. abaqus-2024)",
        name));
}

CaseSpec imported_case_spec(const ImportedCase& imported, std::string_view solver_name,
                            std::string_view source_name, const ImportBasis& basis) {
  CaseSpec spec;
  try {
    spec = schema::parse_case_id(imported.case_id);
    if (spec.solver != SolverKind::builtin)
      throw SuiteInputError(fmt::format(
          "case id '{}' names a solver: write the id as cases.csv of `export` lists it (the "
          "solver is --solver-name)",
          imported.case_id));
    validate_case(spec);  // --set keys and values, algorithms
    require_importable(spec);
  } catch (const schema::SchemaError& e) {
    fail_at(source_name, imported.line, fmt::format("unknown case id: {}", e.what()));
  } catch (const SuiteInputError& e) {
    fail_at(source_name, imported.line, fmt::format("unknown case id: {}", e.what()));
  }
  apply_basis(spec, basis, imported, source_name);
  spec.solver = SolverKind::imported;
  spec.solver_name = std::string(solver_name);
  if (imported.values.option) {
    spec.solver = SolverKind::external;
    spec.solver_option = *imported.values.option;
  }
  return spec;
}

CaseResult grade_imported_case(const ProblemSetup& setup, const CaseSpec& spec,
                               const ImportedCase& imported, std::string_view source_name) {
  const SurfaceNodes surface = surface_nodes(setup);
  const auto row_of = match_rows(surface, imported, source_name);
  const solver::Mesh& mesh = setup.model.mesh;
  const double none = std::nan("");  // not imported: the layout has no shear
  std::vector<solver::Stress> nodal(static_cast<std::size_t>(mesh.n_nodes()));
  std::map<int, const ImportRow*> row_at_node;
  for (std::size_t i = 0; i < row_of.size(); ++i) {
    const ImportRow& row = imported.rows[row_of[i]];
    nodal[surface.path.nodes[i]] = {row.sigma_x, row.sigma_z, none, none};
    row_at_node[surface.path.nodes[i]] = &row;
  }
  // The contact pressures in the contact surface's node order, as CalculiX's are read.
  std::vector<ContactPressureSample> pressures;
  const auto& contact_sides = solver::resolve_edge_set(mesh, setup.pair.contact_surface);
  for (int node : solver::nodes_of_sides(mesh, contact_sides)) {
    const auto it = row_at_node.find(node);
    if (it != row_at_node.end() && it->second->contact_pressure)
      pressures.push_back({mesh.nodes[node].x(), *it->second->contact_pressure});
  }
  CaseResult result;
  result.spec = spec;
  result.status = CaseStatus::converged;
  const ImportedCaseValues& v = imported.values;
  result.wall_seconds = v.wall_seconds.value_or(0.0);
  result.iterations = v.iterations.value_or(0);
  result.n_equations = v.n_equations.value_or(0);
  result.peak_rss_mb = v.peak_rss_mb.value_or(0.0);
  result.n_elements = setup.mesh_info.n_block_elements;
  result.element_size_h = setup.mesh_info.h_contact / setup.length_unit;
  sample_quantities(setup, surface_of_nodal_stresses(setup, nodal), pressures, result);
  result.exact_profile = exact_profile(setup);
  return result;
}

std::vector<CaseResult> grade_imported(const std::vector<ImportedCase>& cases,
                                       std::string_view solver_name, std::string_view source_name,
                                       const ImportBasis& basis) {
  std::vector<CaseSpec> specs;
  for (const auto& c : cases)
    specs.push_back(imported_case_spec(c, solver_name, source_name, basis));
  std::set<std::string> ids;
  for (std::size_t i = 0; i < specs.size(); ++i)
    if (!ids.insert(case_id(specs[i])).second)
      fail_at(source_name, cases[i].line,
              fmt::format("case '{}' is, on the stated basis, the case {} again", cases[i].case_id,
                          case_id(specs[i])));
  std::vector<CaseResult> results(cases.size());
  for (const auto& members : group_by_model(specs)) {
    const ProblemSetup setup = build_problem(specs[members.front()]);
    for (std::size_t i : members)
      results[i] = grade_imported_case(setup, specs[i], cases[i], source_name);
  }
  return results;
}

}  // namespace cs::suites

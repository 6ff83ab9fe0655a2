#include "suites/problem_setup.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "suites/friction_cases.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/problems/interference_fit_parameters.hpp"
#include "suites/problems/problem_builders.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {

ProblemSetup build_problem(const CaseSpec& spec) {
  const ProblemDescriptor& d = problem_descriptor(spec.problem);
  const Parameters params(d.parameters, spec.overrides, to_string(spec.problem));
  return d.build(spec, params);
}

void validate_case(const CaseSpec& spec) {
  const ProblemDescriptor& d = problem_descriptor(spec.problem);
  const Parameters params(d.parameters, spec.overrides, to_string(spec.problem));
  if (declares(d.parameters, "mu"))
    require_frictional_algorithm(spec, params.get("mu"));
  if (declares(d.parameters, "delta_over_b"))
    problems::require_small_interference(spec, params);
  problems::require_half_space_gap_switch(params);
}

namespace problems {

std::vector<ParameterSpec> study_parameters(std::vector<ParameterSpec> extra) {
  auto params = common_parameters(kStudyPOverE);
  if (declares(extra, "mu"))  // a friction problem: FKN as before issue 14 (parameters.hpp)
    params = with_default(std::move(params), "fkn", kFrictionalDefaultFkn);
  params.insert(params.end(), extra.begin(), extra.end());
  return params;
}

ParameterSpec extent_parameter() {
  // Below 1 the block would cut into the refined mesh around the contact; 64 times the study's
  // block already stands for a half-space to well under the discretization error.
  return {"extent",
          1.0,
          1.0,
          64.0,
          true,
          true,
          "the block's width and depth as a multiple of the study's; the mesh within half the "
          "study's extent is unchanged and the rest is stretched outwards"};
}

ParameterSpec half_space_gap_parameter() {
  return {"half_space_gap",
          0.0,
          0.0,
          1.0,
          true,
          true,
          "1: gaps along the block's own normal, as the half-space theory of the exact values "
          "linearizes them; 0: along the target's normal (the first-order tilt term theta u_t "
          "included)"};
}

void require_half_space_gap_switch(const Parameters& params) {
  if (!params.declares("half_space_gap"))
    return;
  const double v = params.get("half_space_gap");
  if (v != 0.0 && v != 1.0)
    throw SuiteInputError(
        fmt::format("--set half_space_gap={}: only 0 (the target's normal) or 1 (the block's "
                    "own normal) is accepted",
                    v));
}

std::vector<ParameterSpec> with_default(std::vector<ParameterSpec> params, std::string_view name,
                                        double value) {
  for (auto& p : params) {
    if (p.name == name) {
      p.default_value = value;
      return params;
    }
  }
  throw std::logic_error(fmt::format("with_default: no parameter '{}'", name));
}

ProblemSetup start_setup(const CaseSpec& spec, const Parameters& params,
                         const StudyMeshSpec& mesh_spec, const solver::RigidProfile& rigid) {
  using solver::Component;
  using solver::NodeSelection;
  namespace sets = study_sets;
  ProblemSetup setup;
  StudyMesh built = build_study_mesh(mesh_spec);
  setup.mesh_info = built.info;
  solver::Model& model = setup.model;
  model.mesh = std::move(built.mesh);
  model.analysis = is_axisymmetric(spec.problem) ? solver::AnalysisType::Axisymmetric
                                                 : solver::AnalysisType::PlaneStrain;
  const double E = setup.p / params.get("p_over_E");
  const double nu = params.get("nu");
  model.materials.assign(model.n_bodies(), solver::Material{E, nu});
  model.materials[model.body_index(sets::kIndenter)].youngs_modulus_E = E * params.get("E_ratio");
  // Symmetry line (plane strain) or axis (axisymmetric): no horizontal displacement.
  model.fix(NodeSelection::node_set(sets::kBlockSymmetry), Component::X);
  if (spec.target == TargetKind::Rigid) {
    model.fix(NodeSelection::node_set("indenter.all"), Component::X);
    model.fix(NodeSelection::node_set("indenter.all"), Component::Z);
    setup.pair = {sets::kBlockContact, rigid};
  } else {
    model.fix(NodeSelection::node_set(sets::kIndenterSymmetry), Component::X);
    setup.pair = {sets::kBlockContact, solver::TargetSurface{sets::kIndenterContact}};
  }
  if (params.declares("half_space_gap") && params.get("half_space_gap") == 1.0)
    setup.pair.gap_normal = solver::GapNormal::ContactSurface;
  return setup;
}

}  // namespace problems
}  // namespace cs::suites

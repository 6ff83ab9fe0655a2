#include "suites/problem_setup.hpp"

#include "suites/problem_catalog.hpp"
#include "suites/problems/problem_builders.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {

ProblemSetup build_problem(const CaseSpec& spec) {
  const Parameters params(problem_info(spec.problem).parameters, spec.overrides,
                          to_string(spec.problem));
  switch (spec.problem) {
    case ProblemId::P_p:
    case ProblemId::P_a:
    case ProblemId::Pprime_p:
    case ProblemId::Pprime_a:
      return problems::build_patch_test(spec, params);
    case ProblemId::H_p:
    case ProblemId::H_a:
      return problems::build_hertz(spec, params);
    case ProblemId::S_1:
    case ProblemId::S_1_3:
    case ProblemId::S_1_7:
      return problems::build_steuermann(spec, params);
    case ProblemId::F_p:
    case ProblemId::F_a:
      return problems::build_flat_punch(spec, params);
  }
  throw SuiteInputError("unknown problem");
}

namespace problems {

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
  return setup;
}

}  // namespace problems
}  // namespace cs::suites

// Frictional contact patch test FP_p (plane strain): two elastically similar blocks with a flat
// interface, pressed by a uniform pressure p and then sheared by a uniform shear tau < mu p.
//
// Geometry: the P_p mesh (suites/study_meshes.hpp): the block 0 < x < a, 0 < z < a and a
// block-shaped second body of the same half-width in -a/4 < z < 0, with matching nodes; both of
// the block's modulus E and nu (E_ratio does not apply: the bodies are elastically similar).
// Boundary conditions: the exact solution is the uniform stress sigma_z = -p, tau_xz = -tau,
// sigma_x = 0 in both bodies (linear displacements, held exactly by Q4 and Q8), so every face
// carries that state's traction: (-tau, -p) on the block's far face z = a; (0, tau) on the
// x = 0 sides and (0, -tau) on the x = a sides of both bodies (a couple that balances the shear's
// moment). The second body's back face z = -a/4 is held: u_z = 0, u_x = eps_x x with eps_x =
// nu (1 + nu) p / E (the lateral expansion under p, plane strain). The block is held in x by
// friction alone. Load steps: the pressure p alone, then p and tau (friction is path dependent).
// Oracle: oracles/frictional_patch_test.hpp (stick: the shear tau is transmitted exactly, no
// slip; tau >= mu p is refused: the stick oracle needs Q < mu P).
// Sampled: tau_max = the largest -tau_xz/p over the block's contact-surface nodes, exact tau/p;
// sigma_z_max = the largest -sigma_z/p, exact 1 (nodal stresses as the case recovers them).
// Run: contact-suite case FP_p --mesh C --element Q4 --algorithm PLM --contact mortar
//      --set mu=0.3 --set tau_over_mu_p=0.5
//
// No axisymmetric counterpart (FP_a): a uniform tau_rz is not an equilibrium state in the r-z
// plane (d tau_rz/dr + d sigma_z/dz + tau_rz/r = tau_rz/r != 0), so no uniform exact solution
// exists (see the oracle's header).

#include <memory>

#include <fmt/format.h>

#include "oracles/frictional_patch_test.hpp"
#include "oracles/invalid_input.hpp"
#include "suites/friction_cases.hpp"
#include "suites/problems/problem_builders.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites::problems {
namespace {

using Eigen::Vector2d;

/// The current loads, read by the model's callables: a load step only changes these numbers.
struct PatchLoad {
  double p = 0.0;
  double tau = 0.0;
};

/// -tau_xz/p and -sigma_z/p of the oracle's uniform state; its InvalidInput as SuiteInputError.
oracles::PlaneStress exact_state(double p, double tau, double mu) {
  try {
    return oracles::frictional_patch_stick_stress({p, tau, mu}, {0.0, 0.0});
  } catch (const oracles::InvalidInput& e) {
    throw SuiteInputError(fmt::format("FP_p: {}", e.what()));
  }
}

void add_uniform_state_loads(solver::Model& model, const std::shared_ptr<PatchLoad>& load,
                             double eps_x_per_p) {
  namespace sets = study_sets;
  using solver::Component;
  using solver::NodeSelection;
  model.loads.add_traction(sets::kBlockFarZ,
                           [load](const Vector2d&) { return Vector2d(-load->tau, -load->p); });
  for (const char* side : {sets::kBlockSymmetry, sets::kIndenterSymmetry}) {
    model.loads.add_traction(side, [load](const Vector2d&) { return Vector2d(0.0, load->tau); });
  }
  for (const char* side : {sets::kBlockFarX, sets::kIndenterSide}) {
    model.loads.add_traction(side, [load](const Vector2d&) { return Vector2d(0.0, -load->tau); });
  }
  model.fix(NodeSelection::node_set(sets::kIndenterLoad), Component::Z);
  model.prescribe(NodeSelection::node_set(sets::kIndenterLoad), Component::X,
                  [load, eps_x_per_p](const Vector2d& x) { return eps_x_per_p * load->p * x.x(); });
}

}  // namespace

ProblemSetup build_frictional_patch(const CaseSpec& spec, const Parameters& params) {
  const double mu = params.get("mu");
  require_frictional_algorithm(spec, mu);
  if (spec.target == TargetKind::Rigid) {
    throw SuiteInputError(
        "FP_p: no rigid target: the second body must expand laterally with the block (similar "
        "materials), a rigid plane would shear the interface under p alone");
  }
  ProblemSetup setup;
  const double p = setup.p;
  const double tau = params.get("tau_over_mu_p") * mu * p;
  const oracles::PlaneStress exact = exact_state(p, tau, mu);

  StudyMesh built = build_study_mesh({.problem = spec.problem,
                                      .level = spec.mesh,
                                      .element = to_solver(spec.element),
                                      .a = 1.0,
                                      .R = 0.0,
                                      .b = 0.0,
                                      .r_e = 0.0,
                                      .options = {}});
  setup.mesh_info = built.info;
  solver::Model& model = setup.model;
  model.mesh = std::move(built.mesh);
  model.analysis = solver::AnalysisType::PlaneStrain;
  const double E = p / params.get("p_over_E"), nu = params.get("nu");
  model.materials.assign(model.n_bodies(), solver::Material{E, nu});
  auto load = std::make_shared<PatchLoad>(PatchLoad{p, tau});
  add_uniform_state_loads(model, load, nu * (1.0 + nu) / E);
  setup.pair = {study_sets::kBlockContact, solver::TargetSurface{study_sets::kIndenterContact}};
  setup.load_steps = {{"normal",
                       [load, p] {
                         *load = {p, 0.0};
                       }},
                      {"shear", [load, p, tau] {
                         *load = {p, tau};
                       }}};

  setup.length_unit = setup.contact_half_width_a = 1.0;
  setup.exact_pressure_over_p = [](double x) { return x <= 1.0 ? 1.0 : 0.0; };
  setup.quantities.push_back({schema::Quantity::tau_max, SamplePoint::MaxOnSurface,
                              StressComponent::TauXZ, -exact.tau_xz / p, std::nullopt});
  setup.quantities.push_back({schema::Quantity::sigma_z_max, SamplePoint::MaxOnSurface,
                              StressComponent::SigmaZ, -exact.sigma_z / p, std::nullopt});
  return setup;
}

}  // namespace cs::suites::problems

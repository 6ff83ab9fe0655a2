// Contact patch tests P_p, P_a (matching nodes) and P'_p, P'_a (non-matching nodes).
//
// Geometry (study Eq. 1, 7; Figure 2a, 3a, 3a'): the half slab 0 < x < a, 0 < z < h (h = a),
// x = r in axisymmetry; a stiff block indenter of the same half-width a in z < 0.
// Boundary conditions: symmetry u_x = 0 on x = 0 (Eq. 2; the axis in P_a); pressure p on
// z = h pushing the slab onto the indenter (Eq. 3); x = a free (Eq. 4); frictionless contact
// on z = 0 (Eq. 5); the indenter's back face held in z (u_z = 0), its x = 0 edge symmetric.
// Oracle: the uniform stress sigma_z = -p, sigma_x = tau_xz = 0 (Eq. 6, 8).
// Sampled: sigma_z_max, the largest -sigma_z/p over the slab's contact-surface nodes
// (nodal stresses as the case recovers them, --recovery), exact 1 (the study's Tables 3-6).
// Run: contact-suite case Pprime_p --mesh C --element Q4 --algorithm LMP --contact mortar

#include "oracles/patch_test.hpp"
#include "suites/problems/problem_builders.hpp"

namespace cs::suites::problems {

ProblemSetup build_patch_test(const CaseSpec& spec, const Parameters& params) {
  StudyMeshSpec mesh;
  mesh.problem = spec.problem;
  mesh.level = spec.mesh;
  mesh.element = to_solver(spec.element);
  mesh.a = 1.0;
  // A rigid plane z = 0 with the rigid side z < 0: its normal points into the slab (+z).
  const solver::RigidProfile rigid = solver::RigidPlane{{0.0, 0.0}, {0.0, 1.0}};
  ProblemSetup setup = start_setup(spec, params, mesh, rigid);
  setup.length_unit = mesh.a;
  setup.contact_half_width_a = mesh.a;

  setup.model.loads.add_pressure(study_sets::kBlockFarZ, setup.p);
  if (spec.target == TargetKind::Discretized) {
    setup.model.fix(solver::NodeSelection::node_set(study_sets::kIndenterLoad),
                    solver::Component::Z);
  }
  // The exact stress is uniform: read it at the origin of the contact surface.
  const oracles::PatchTestLoad load{setup.p};
  const double exact = is_axisymmetric(spec.problem)
                           ? -oracles::patch_test_axi_stress(load, {0.0, 0.0}).sigma_z / setup.p
                           : -oracles::patch_test_plane_stress(load, {0.0, 0.0}).sigma_z / setup.p;
  setup.exact_pressure_over_p = [a = mesh.a, exact](double x) { return x <= a ? exact : 0.0; };
  setup.quantities.push_back({schema::Quantity::sigma_z_max, SamplePoint::MaxOnSurface,
                              StressComponent::SigmaZ, exact, std::nullopt});
  return setup;
}

}  // namespace cs::suites::problems

// Interference fits IF_p and IF_a: a solid shaft in a thick ring (plane strain) and a solid
// sphere in a thick spherical shell (axisymmetric, the r-z plane), of radial interference delta:
// conformal contact along a whole quarter circle.
//
// Geometry: quarter models, x (r) >= 0, z >= 0. The ring (shell), body "block", is the quarter
// annulus b < r < c, c = b / b_over_c; the shaft (sphere), body "indenter", the quarter disc of
// radius b + delta: the interference is an initial overlap of delta along the whole arc that the
// contact must resolve (g0 = -delta at every contact point). Both are curved structured meshes
// (solver/mesh/circular_sector.hpp) with 16, 32, 64 elements along the arc at C, M, F (the arc
// element b pi/32 = 0.098 b at C, between H_p's a/4 and a/2), so the two arcs' nodes sit at the
// same angles (a faceted Q4 arc with mismatched nodes would overlap by b (dtheta)^2 / 8 = 1.2e-3 b
// at C, more than the default delta). The ring has square_radial_count radial elements (radii
// growing geometrically), the shaft a core square of side b/2 and n_arc/4 elements across its
// curved blocks; M and F double every count.
// Boundary conditions: symmetry on both bodies: u_x = 0 on x = 0 (the axis, IF_a), u_z = 0 on
// z = 0. No load: the overlap alone loads the fit. The contact surface is the ring's bore, the
// target the shaft's arc.
// Materials: ring E, shaft E_ratio x E, both nu; E is chosen so that the exact pressure p is 1
// (the oracle's p is linear in E), the normalizing pressure of the problem.
// Oracle: oracles/interference_fit.hpp (Lame, Timoshenko & Goodier Secs. 28 and 137): the
// contact pressure p, uniform along the arc; delta/b <= 1e-2 is the oracle's small-strain limit
// (beyond it: one-line error).
// Sampled, from the contact solution (suites/arc_sampling.hpp):
//   p_mean = the interface's resultant normal force over the exact one (p pi b/2 per unit
//     thickness, p b^2 per radian for the sphere's quarter section): the mean pressure over p;
//   p_arc = the nodal contact pressure over p at the node of the bore where |p(theta)/p - 1| is
//     largest (its error is the largest deviation along the arc, signed).
// Measured (default delta/b = 1e-3, F): LM (LMP = PLM = MPC) ss and mortar give the mean
// pressure within 0.01 % (IF_p) and 0.05 % (IF_a); the sphere's LM error has a floor of about
// 0.4 delta/b (+0.039 % with Q8) from the overlapped geometry the linear oracle ignores (+0.003 %
// at delta/b = 1e-5). PM and AL are low by the penalty's series compliance kappa h/(1 + kappa h),
// kappa = p b/(E delta) (-0.87 %, -1.65 % on F: FTOLN = 0.1 h never triggers an augmentation
// for an overlap of 1e-3 b). Node-to-surface with Q8 shows no weakness with LM (the two arcs'
// nodes match: +0.003 % along the arc in IF_p); with a penalty in the sphere, the node on the
// axis (whose Q8 weight r ds is 0) carries 0.93 p (ns) and 0.12 p (mortar).
// MPC ties every point within the pinball to g = 0 from the start (the overlap closed exactly,
// no separation): on a fit that stays closed everywhere it is the Lagrange multiplier solution.
// Run: contact-suite case IF_p --mesh F --element Q8 --algorithm LMP --contact ns

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "oracles/interference_fit.hpp"
#include "oracles/invalid_input.hpp"
#include "solver/mesh/circular_sector.hpp"
#include "solver/mesh/mesh_merge.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "suites/problems/interference_fit_parameters.hpp"
#include "suites/problems/problem_builders.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites::problems {
namespace {

using solver::Component;
using solver::NodeSelection;

constexpr int kArcElementsC = 16;  ///< elements along the quarter arc at C

/// The oracle's pressure of the fit (cylinder or sphere); its InvalidInput as SuiteInputError.
double exact_pressure(const oracles::InterferenceFit& fit, bool sphere, ProblemId id) {
  try {
    return sphere ? oracles::interference_fit_sphere_pressure(fit)
                  : oracles::interference_fit_cylinder_pressure(fit);
  } catch (const oracles::InvalidInput& e) {
    throw SuiteInputError(fmt::format("{}: {}", to_string(id), e.what()));
  }
}

/// The ring (block) and the shaft (indenter), merged; their sets named as the study's.
solver::Mesh fit_mesh(ElementType type, int n_arc, int n_radial, double b, double c, double delta) {
  solver::Mesh ring = solver::make_quarter_annulus({.type = type,
                                                    .inner_radius = b,
                                                    .outer_radius = c,
                                                    .n_arc = n_arc,
                                                    .n_radial = n_radial,
                                                    .body_name = study_sets::kBlock});
  solver::rename_set(ring, "inner", "contact");
  solver::rename_set(ring, "z_axis", "symmetry");
  solver::Mesh shaft = solver::make_quarter_disc({.type = type,
                                                  .radius = b + delta,
                                                  .n_arc = n_arc,
                                                  .n_radial = n_arc / 4,
                                                  .core_fraction = 0.5,
                                                  .body_name = study_sets::kIndenter});
  solver::rename_set(shaft, "arc", "contact");
  solver::rename_set(shaft, "z_axis", "symmetry");
  return solver::merge_bodies({ring, shaft});
}

StudyMeshInfo fit_mesh_info(const solver::Mesh& mesh, int n_arc, double b, double c, double delta) {
  StudyMeshInfo info;
  for (int body : mesh.element_body)
    ++(body == 0 ? info.n_block_elements : info.n_indenter_elements);
  info.n_nodes = mesh.n_nodes();
  info.block_width = info.block_depth = c;
  info.indenter_half_width = info.indenter_height = b + delta;
  info.h_contact = 2.0 * b * std::sin(std::numbers::pi / (4.0 * n_arc));  // the bore's chord
  info.h_background = info.h_contact;
  info.indenter_surface_elements = n_arc;
  return info;
}

}  // namespace

void require_small_interference(const CaseSpec& spec, const Parameters& params) {
  const double b = 1.0, nu = params.get("nu");
  const oracles::InterferenceFit fit{
      b, b / params.get("b_over_c"), params.get("delta_over_b") * b, {1.0, nu}, {1.0, nu}};
  exact_pressure(fit, spec.problem == ProblemId::IF_a, spec.problem);
}

ProblemSetup build_interference_fit(const CaseSpec& spec, const Parameters& params) {
  const bool sphere = spec.problem == ProblemId::IF_a;
  if (spec.target == TargetKind::Rigid) {
    throw SuiteInputError(
        fmt::format("{}: no rigid target: the interference is shared by the shaft's and the ring's "
                    "compliance (a rigid shaft is --set E_ratio=1e6)",
                    to_string(spec.problem)));
  }
  require_small_interference(spec, params);
  const double b = 1.0, c = b / params.get("b_over_c"), delta = params.get("delta_over_b") * b;
  const double nu = params.get("nu"), E_ratio = params.get("E_ratio");
  oracles::InterferenceFit fit{b, c, delta, {E_ratio, nu}, {1.0, nu}};
  const double E = 1.0 / exact_pressure(fit, sphere, spec.problem);  // p = 1 (linear in E)
  fit.inner.E = E_ratio * E;
  fit.outer.E = E;

  ProblemSetup setup;
  setup.p = exact_pressure(fit, sphere, spec.problem);
  const int n_arc = kArcElementsC * level_factor(spec.mesh);
  const int n_radial = solver::square_radial_count(b, c, kArcElementsC) * level_factor(spec.mesh);
  solver::Model& model = setup.model;
  model.mesh = fit_mesh(to_solver(spec.element), n_arc, n_radial, b, c, delta);
  setup.mesh_info = fit_mesh_info(model.mesh, n_arc, b, c, delta);
  model.analysis = sphere ? solver::AnalysisType::Axisymmetric : solver::AnalysisType::PlaneStrain;
  model.materials.assign(model.n_bodies(), solver::Material{E, nu});
  model.materials[model.body_index(study_sets::kIndenter)].youngs_modulus_E = E_ratio * E;
  for (const char* body : {study_sets::kBlock, study_sets::kIndenter}) {
    model.fix(NodeSelection::node_set(fmt::format("{}.symmetry", body)), Component::X);
    model.fix(NodeSelection::node_set(fmt::format("{}.x_axis", body)), Component::Z);
  }
  setup.pair = {study_sets::kBlockContact, solver::TargetSurface{study_sets::kIndenterContact}};

  setup.length_unit = setup.contact_half_width_a = b;
  setup.exact_pressure_over_p = [b](double x) { return x <= b ? 1.0 : 0.0; };
  // Quarter arc: p pi b / 2 per unit thickness; p integral_0^{pi/2} b cos(phi) b dphi = p b^2
  // per radian for the sphere (r = b cos phi on the section).
  setup.exact_interface_force = setup.p * (sphere ? b * b : std::numbers::pi * b / 2.0);
  setup.quantities.push_back({schema::Quantity::p_mean, SamplePoint::InterfaceMeanPressure,
                              StressComponent::SigmaZ, 1.0, std::nullopt});
  setup.quantities.push_back({schema::Quantity::p_arc, SamplePoint::ArcPressureExtreme,
                              StressComponent::SigmaZ, 1.0, std::nullopt});
  return setup;
}

}  // namespace cs::suites::problems

// Flat punches with sharp corners, singular: F_p (Sadowsky, plane strain) and F_a
// (Harding-Sneddon, axisymmetric).
//
// Geometry (study Eq. 33, 40; Figure 2d, 3d): the half block 0 < x < 4a, 0 < z < 4a (x = r
// for F_a); the stiff punch of half-width a in z < 0.
// Boundary conditions: symmetry u_x = 0 on x = 0 (Eq. 34; the axis for F_a); on the far faces
// the tractions of a uniform strip load p on |x| < a (Eq. 35-36) for F_p, of Boussinesq's point
// load P = pi a^2 p (Eq. 41-42) for F_a; frictionless contact on z = 0 (Eq. 38, 44). The block
// is held vertically only by the punch, whose back face is held in z.
// Oracle: Sadowsky's pressure (Eq. 39), Harding and Sneddon's (Eq. 45): infinite at the
// contact edge x = a, so the sampled stress must diverge under refinement (Eq. 47).
// Sampled: sigma_c_star = -sigma_z/p at the contact edge (x = a, z = 0), nodal (the study's
// Tables 13-14).
// Run: contact-suite case F_p --mesh F --element Q8 --algorithm PM --contact ns

#include <cmath>
#include <limits>

#include "oracles/boussinesq.hpp"
#include "oracles/flat_punch.hpp"
#include "oracles/strip_load.hpp"
#include "suites/problems/problem_builders.hpp"

namespace cs::suites::problems {

ProblemSetup build_flat_punch(const CaseSpec& spec, const Parameters& params) {
  using Eigen::Vector2d;
  const double a = 1.0;
  const bool axi = spec.problem == ProblemId::F_a;
  StudyMeshSpec mesh{.problem = spec.problem,
                     .level = spec.mesh,
                     .element = to_solver(spec.element),
                     .a = a,
                     .options = {}};
  mesh.extent = params.get("extent");
  const solver::RigidProfile rigid = solver::SharpFlatPunch{{0.0, 0.0}, {0.0, 1.0}, a};
  ProblemSetup setup = start_setup(spec, params, mesh, rigid);
  setup.length_unit = setup.contact_half_width_a = a;
  // The mean pressure of the exact solutions is the study's p (Eq. 39, 45).
  setup.p = axi ? oracles::harding_sneddon_mean_pressure({a, M_PI * a * a})
                : oracles::sadowsky_mean_pressure({a, 2.0 * a});

  if (axi) {
    const oracles::BoussinesqLoad field{M_PI * a * a * setup.p, params.get("nu")};
    setup.model.loads.add_traction(study_sets::kBlockFarZ, [field](const Vector2d& x) {
      const auto s = oracles::boussinesq_stress(field, {x.x(), x.y()});
      return Vector2d(s.tau_rz, s.sigma_z);
    });
    setup.model.loads.add_traction(study_sets::kBlockFarX, [field](const Vector2d& x) {
      const auto s = oracles::boussinesq_stress(field, {x.x(), x.y()});
      return Vector2d(s.sigma_r, s.tau_rz);
    });
  } else {
    const oracles::StripLoad field{a, setup.p};
    setup.model.loads.add_traction(study_sets::kBlockFarZ, [field](const Vector2d& x) {
      const auto s = oracles::strip_load_stress(field, {x.x(), x.y()});
      return Vector2d(s.tau_xz, s.sigma_z);
    });
    setup.model.loads.add_traction(study_sets::kBlockFarX, [field](const Vector2d& x) {
      const auto s = oracles::strip_load_stress(field, {x.x(), x.y()});
      return Vector2d(s.sigma_x, s.tau_xz);
    });
  }
  // Infinite at the edge x = a (the oracles refuse it; the profile leaves it out).
  if (axi) {
    setup.exact_pressure_over_p = [punch = oracles::HardingSneddonPunch{a, M_PI * a * a},
                                   p = setup.p](double r) {
      return oracles::harding_sneddon_pressure(punch, r) / p;
    };
  } else {
    setup.exact_pressure_over_p = [punch = oracles::SadowskyPunch{a, 2.0 * a},
                                   p = setup.p](double x) {
      return oracles::sadowsky_pressure(punch, x) / p;
    };
  }
  if (spec.target == TargetKind::Discretized) {
    setup.model.fix(solver::NodeSelection::node_set(study_sets::kIndenterLoad),
                    solver::Component::Z);
  }
  setup.quantities.push_back({schema::Quantity::sigma_c_star, SamplePoint::AtEdge,
                              StressComponent::SigmaZ, std::numeric_limits<double>::infinity(),
                              std::nullopt});
  return setup;
}

}  // namespace cs::suites::problems

// Hertz contact H_p (a cylinder, plane strain) and H_a (a sphere, axisymmetric).
//
// Geometry (study Eq. 9, 17; Figure 2b, 3b): H_p the half block 0 < x < 4a, 0 < z < 4a;
// H_a the cylinder 0 < r < 8a, 0 < z < 8a; a stiff circular indenter of radius R in z < 0,
// R chosen so that the contact half-width is a (Eq. 16: a = 8R(1-nu^2)p/(pi E), p = P/(2a);
// Eq. 23: a = 3 pi R(1-nu^2)p/(4E), p = P/(pi a^2)).
// Boundary conditions: symmetry u_x = 0 on x = 0 (Eq. 10; the axis for H_a); on the far faces
// the exact interior tractions — McEwen's field (Eq. 11-12) for H_p, Boussinesq's point load
// (Eq. 18-19) for H_a; frictionless contact on z = 0 (Eq. 14, 21). The block is held
// vertically only by the indenter, whose back face is held in z.
// Oracle: Hertz's pressure (Eq. 15, 22): -sigma_z(0,0)/p = 4/pi (H_p), 3/2 (H_a); at the
// surface sigma_x = sigma_z (Eq. 15), read from McEwen's field at the origin.
// Sampled: sigma_c = -sigma_z(0,0)/p (and for H_p sigma_h = -sigma_x(0,0)/p), the nodal
// stresses at the node on the axis (the study's Tables 7-9).
// Run: contact-suite case H_p --mesh F --element Q4 --algorithm LMP --contact ss

#include <cmath>

#include "oracles/boussinesq.hpp"
#include "oracles/hertz_axi.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/mcewen.hpp"
#include "suites/problems/problem_builders.hpp"

namespace cs::suites::problems {
namespace {

using Eigen::Vector2d;

/// Tractions t = sigma . n on the block's far faces: z = depth (n = +z), x = width (n = +x).
void add_far_field(ProblemSetup& setup, const std::function<Vector2d(const Vector2d&)>& on_z_face,
                   const std::function<Vector2d(const Vector2d&)>& on_x_face) {
  setup.model.loads.add_traction(study_sets::kBlockFarZ, on_z_face);
  setup.model.loads.add_traction(study_sets::kBlockFarX, on_x_face);
}

ProblemSetup build_hertz_plane(const CaseSpec& spec, const Parameters& params) {
  const double a = 1.0, p = 1.0;
  const double E = p / params.get("p_over_E"), nu = params.get("nu");
  const double R = M_PI * E * a / (8.0 * (1.0 - nu * nu) * p);  // Eq. 16 solved for R
  const auto contact = oracles::hertz_plane_contact({R, E, nu, 2.0 * a * p});

  StudyMeshSpec mesh{.problem = spec.problem,
                     .level = spec.mesh,
                     .element = to_solver(spec.element),
                     .a = contact.contact_half_width_a,
                     .R = R,
                     .options = {}};
  mesh.extent = params.get("extent");
  const solver::RigidProfile rigid = solver::RigidCircle{{0.0, -R}, R};
  ProblemSetup setup = start_setup(spec, params, mesh, rigid);
  setup.p = contact.p_mean;
  setup.length_unit = setup.contact_half_width_a = contact.contact_half_width_a;

  const oracles::McEwenLoad field{contact.contact_half_width_a, contact.p_mean};
  add_far_field(
      setup,
      [field](const Vector2d& x) {
        const auto s = oracles::mcewen_stress(field, {x.x(), x.y()});
        return Vector2d(s.tau_xz, s.sigma_z);
      },
      [field](const Vector2d& x) {
        const auto s = oracles::mcewen_stress(field, {x.x(), x.y()});
        return Vector2d(s.sigma_x, s.tau_xz);
      });
  setup.exact_pressure_over_p = [contact](double x) {
    return oracles::hertz_plane_pressure(contact, x) / contact.p_mean;
  };
  const auto surface = oracles::mcewen_stress(field, {0.0, 0.0});
  const double sigma_c = oracles::hertz_plane_pressure(contact, 0.0) / contact.p_mean;
  setup.quantities.push_back({schema::Quantity::sigma_c, SamplePoint::AtAxis,
                              StressComponent::SigmaZ, sigma_c, std::nullopt});
  setup.quantities.push_back({schema::Quantity::sigma_h, SamplePoint::AtAxis,
                              StressComponent::SigmaX, -surface.sigma_x / contact.p_mean,
                              std::nullopt});
  setup.quantities.push_back({schema::Quantity::contact_half_width, SamplePoint::ContactEdge,
                              StressComponent::SigmaZ, 1.0, std::nullopt});
  return setup;
}

ProblemSetup build_hertz_axi(const CaseSpec& spec, const Parameters& params) {
  const double a = 1.0, p = 1.0;
  const double E = p / params.get("p_over_E"), nu = params.get("nu");
  const double R = 4.0 * E * a / (3.0 * M_PI * (1.0 - nu * nu) * p);  // Eq. 23 solved for R
  const auto contact = oracles::hertz_axi_contact({R, E, nu, M_PI * a * a * p});

  StudyMeshSpec mesh{.problem = spec.problem,
                     .level = spec.mesh,
                     .element = to_solver(spec.element),
                     .a = contact.contact_radius_a,
                     .R = R,
                     .options = {}};
  mesh.extent = params.get("extent");
  const solver::RigidProfile rigid = solver::RigidCircle{{0.0, -R}, R};
  ProblemSetup setup = start_setup(spec, params, mesh, rigid);
  setup.p = contact.p_mean;
  setup.length_unit = setup.contact_half_width_a = contact.contact_radius_a;

  // Boussinesq's point load P = pi a^2 p stands in for the Hertz pressure far away (Eq. 18-19).
  const oracles::BoussinesqLoad field{M_PI * a * a * contact.p_mean, nu};
  add_far_field(
      setup,
      [field](const Vector2d& x) {
        const auto s = oracles::boussinesq_stress(field, {x.x(), x.y()});
        return Vector2d(s.tau_rz, s.sigma_z);
      },
      [field](const Vector2d& x) {
        const auto s = oracles::boussinesq_stress(field, {x.x(), x.y()});
        return Vector2d(s.sigma_r, s.tau_rz);
      });
  setup.exact_pressure_over_p = [contact](double r) {
    return oracles::hertz_axi_pressure(contact, r) / contact.p_mean;
  };
  setup.quantities.push_back(
      {schema::Quantity::sigma_c, SamplePoint::AtAxis, StressComponent::SigmaZ,
       oracles::hertz_axi_pressure(contact, 0.0) / contact.p_mean, std::nullopt});
  setup.quantities.push_back({schema::Quantity::contact_half_width, SamplePoint::ContactEdge,
                              StressComponent::SigmaZ, 1.0, std::nullopt});
  return setup;
}

}  // namespace

ProblemSetup build_hertz(const CaseSpec& spec, const Parameters& params) {
  ProblemSetup setup = spec.problem == ProblemId::H_a ? build_hertz_axi(spec, params)
                                                      : build_hertz_plane(spec, params);
  if (spec.target == TargetKind::Discretized) {
    setup.model.fix(solver::NodeSelection::node_set(study_sets::kIndenterLoad),
                    solver::Component::Z);
  }
  return setup;
}

}  // namespace cs::suites::problems

// Cattaneo-Mindlin partial slip CM_p (plane strain): a cylinder pressed onto a block of the same
// material (Dundurs beta = 0: the normal and tangential problems uncouple), then pulled sideways
// by Q < mu P in increments.
//
// Geometry: both bodies whole (a tangential load breaks the x = 0 symmetry): the block
// -4a < x < 4a, 0 < z < 4a, and the cylinder of radius R over -4a < x < 4a, from its contact
// surface z = -(R - (R^2 - x^2)^(1/2)) to its back z = -4a; both uniform with H_p's element size
// at the contact (a/4, a/8, a/16 at C, M, F), so their contact nodes share x positions.
// R = pi E a / (16 p (1 - nu^2)) gives the half-width a for the mean pressure p of two similar
// bodies (Johnson Eq. 4.43: a^2 = 8 P R (1 - nu^2) / (pi E), P = 2 a p).
// Boundary conditions: every far face carries the exact interior tractions of the half-space
// field: McEwen's (mcewen.hpp, the normal load, p the mean pressure = pi p0 / 4) plus two
// semi-elliptic tangential fields (hertz_tangential_traction.hpp: mu p0 on a and -mu p0 c/a on
// c, the Cattaneo-Mindlin shear); the cylinder carries the same field mirrored (z -> -z, the
// tangential part reversed: it is pulled the other way). The loads are self-equilibrated; a
// determinate symmetric support (the cylinder's back centre held in x, its back corners in z)
// removes the rigid-body modes only. Load steps: P alone, then Q in `q_increments` equal steps,
// each with the exact field of its own Q (monotonic loading: the same as Q at once).
// Oracle: oracles/cattaneo_mindlin.hpp (c = a (1 - Q/(mu P))^(1/2); Q >= mu P is refused).
// Sampled: tau_max = the largest shear traction of the contact solution over p (exact q_peak / p =
// (4/pi)(mu Q / P)^(1/2)): the traction has a cusp at x = c that nodal stress recovery smooths
// (F, Q4, PLM ss: nodal -tau_xz peak -18 %, the contact's +3 %); c_over_a from the contact's
// stick/slip states (midway between the last sticking and the first slipping node on each side,
// averaged); sigma_c = -sigma_z(0, 0)/p = 4/pi as H_p. Run: contact-suite case CM_p --mesh F
// --element Q4 --algorithm PLM --contact ss

#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "oracles/cattaneo_mindlin.hpp"
#include "oracles/hertz_tangential_traction.hpp"
#include "oracles/invalid_input.hpp"
#include "oracles/mcewen.hpp"
#include "solver/mesh/mesh_merge.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/structured_block.hpp"
#include "suites/friction_cases.hpp"
#include "suites/problems/problem_builders.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites::problems {
namespace {

using Eigen::Vector2d;
using oracles::PlaneStress;

constexpr double kHalfSize = 4.0;  ///< L / a: the bodies' half-width and depth

/// The current load: the oracle's contact for the current Q (its tangential field off at Q = 0).
struct MindlinLoad {
  oracles::McEwenLoad normal{1.0, 1.0};
  oracles::CattaneoMindlinContact contact{};
  bool tangential = false;
};

/// The lower body's (block's) half-space stress at (x, z >= 0); `sign` -1 reverses the shear.
PlaneStress field(const MindlinLoad& load, double x, double z, double sign) {
  PlaneStress s = oracles::mcewen_stress(load.normal, {x, z});
  if (!load.tangential)
    return s;
  const auto& c = load.contact;
  const double q0 = sign * c.mu * c.p0;
  const PlaneStress t1 =
      oracles::hertz_tangential_traction_stress({c.contact_half_width_a, q0}, {x, z});
  s.sigma_x += t1.sigma_x, s.sigma_z += t1.sigma_z, s.tau_xz += t1.tau_xz;
  if (c.c_over_a > 0.0) {
    const PlaneStress t2 =
        oracles::hertz_tangential_traction_stress({c.stick_half_width_c, -q0 * c.c_over_a}, {x, z});
    s.sigma_x += t2.sigma_x, s.sigma_z += t2.sigma_z, s.tau_xz += t2.tau_xz;
  }
  return s;
}

/// The stress of the block (z >= 0) or of the cylinder (z < 0: the mirrored field).
PlaneStress stress_at(const MindlinLoad& load, const Vector2d& x) {
  if (x.y() >= 0.0)
    return field(load, x.x(), x.y(), 1.0);
  PlaneStress s = field(load, x.x(), -x.y(), -1.0);
  s.tau_xz = -s.tau_xz;
  return s;
}

/// t = sigma n on a face of outward normal n = (nx, nz).
void add_face(solver::Model& model, const std::string& set,
              const std::shared_ptr<const MindlinLoad>& load, Vector2d n) {
  model.loads.add_traction(set, [load, n](const Vector2d& x) {
    const PlaneStress s = stress_at(*load, x);
    return Vector2d(s.sigma_x * n.x() + s.tau_xz * n.y(), s.tau_xz * n.x() + s.sigma_z * n.y());
  });
}

solver::Mesh mindlin_mesh(ElementType type, int n, double a, double R) {
  const double L = kHalfSize * a;
  solver::BlockSpec block;
  block.type = type;
  block.origin = {-L, 0.0};
  block.size = {2.0 * L, L};
  block.nx = 2 * n;
  block.nz = n;
  block.body_name = study_sets::kBlock;
  solver::Mesh lower = solver::make_block(block);
  solver::rename_set(lower, "bottom", "contact");
  solver::rename_set(lower, "top", "far_z");
  solver::MappedBlockSpec cyl;
  cyl.type = type;
  for (int i = 0; i <= 2 * n; ++i)
    cyl.u.push_back(static_cast<double>(i) / (2 * n));
  for (int j = 0; j <= n; ++j)
    cyl.v.push_back(static_cast<double>(j) / n);
  cyl.map = [L, R](double u, double v) {
    const double x = -L + 2.0 * L * u;
    const double surface = -(R - std::sqrt(R * R - x * x));
    return Vector2d(x, -L + v * (L + surface));
  };
  cyl.body_name = study_sets::kIndenter;
  solver::Mesh upper = solver::make_mapped_block(cyl);
  solver::rename_set(upper, "top", "contact");
  return solver::merge_bodies({lower, upper});
}

oracles::CattaneoMindlinContact solve_oracle(const oracles::CattaneoMindlinPlane& problem) {
  try {
    return oracles::cattaneo_mindlin_contact(problem);
  } catch (const oracles::InvalidInput& e) {
    throw SuiteInputError(fmt::format("CM_p: {}", e.what()));
  }
}

void hold_rigid_body_modes(solver::Model& model) {
  const std::vector<int>& back = model.mesh.node_sets.at("indenter.bottom");  // sorted by x
  model.fix(solver::NodeSelection::list({back[back.size() / 2]}, "cylinder back centre"),
            solver::Component::X);
  model.fix(solver::NodeSelection::list({back.front(), back.back()}, "cylinder back corners"),
            solver::Component::Z);
}

}  // namespace

ProblemSetup build_cattaneo_mindlin(const CaseSpec& spec, const Parameters& params) {
  const double mu = params.get("mu");
  require_frictional_algorithm(spec, mu);
  if (spec.target == TargetKind::Rigid)
    throw SuiteInputError("CM_p: no rigid target: Cattaneo-Mindlin needs two similar bodies");
  ProblemSetup setup;
  const double a = 1.0, p = setup.p;
  const double E = p / params.get("p_over_E"), nu = params.get("nu");
  const double R = M_PI * E * a / (16.0 * p * (1.0 - nu * nu));
  const double P = 2.0 * a * p, Q = params.get("Q_over_mu_P") * mu * P;
  const auto exact = solve_oracle({R, E, nu, P, Q, mu});

  const int n = 16 * level_factor(spec.mesh);
  solver::Model& model = setup.model;
  model.mesh = mindlin_mesh(to_solver(spec.element), n, a, R);
  model.analysis = solver::AnalysisType::PlaneStrain;
  model.materials.assign(model.n_bodies(), solver::Material{E, nu});
  auto load = std::make_shared<MindlinLoad>();
  load->normal = {exact.contact_half_width_a, exact.p_mean};
  load->contact = exact;
  load->tangential = Q > 0.0;
  add_face(model, "block.far_z", load, {0.0, 1.0});
  add_face(model, "indenter.bottom", load, {0.0, -1.0});
  for (const char* body : {"block", "indenter"}) {
    add_face(model, std::string(body) + ".left", load, {-1.0, 0.0});
    add_face(model, std::string(body) + ".right", load, {1.0, 0.0});
  }
  hold_rigid_body_modes(model);
  setup.pair = {study_sets::kBlockContact, solver::TargetSurface{"indenter.contact"}};
  setup.load_steps.push_back({"normal", [load] { load->tangential = false; }});
  const int steps = static_cast<int>(std::lround(params.get("q_increments")));
  for (int k = 1; k <= steps; ++k) {
    auto at_k = solve_oracle({R, E, nu, P, Q * k / steps, mu});
    setup.load_steps.push_back({fmt::format("tangential {}/{}", k, steps), [load, at_k, Q] {
                                  load->contact = at_k;
                                  load->tangential = Q > 0.0;
                                }});
  }

  setup.mesh_info.n_block_elements = 2 * n * n;
  setup.mesh_info.n_indenter_elements = 2 * n * n;
  setup.mesh_info.n_nodes = model.mesh.n_nodes();
  setup.mesh_info.block_width = 2.0 * kHalfSize * a;
  setup.mesh_info.block_depth = kHalfSize * a;
  setup.mesh_info.h_contact = setup.mesh_info.h_background = kHalfSize * a / n;
  setup.length_unit = setup.contact_half_width_a = exact.contact_half_width_a;
  setup.exact_pressure_over_p = [exact](double x) {
    return oracles::cattaneo_mindlin_pressure(exact, x) / exact.p_mean;
  };
  using schema::Quantity;
  setup.quantities.push_back({Quantity::tau_max, SamplePoint::ContactPeakShear,
                              StressComponent::TauXZ, exact.q_peak_over_p_mean, std::nullopt});
  setup.quantities.push_back({Quantity::c_over_a, SamplePoint::StickZoneEdge,
                              StressComponent::TauXZ, exact.c_over_a, std::nullopt});
  setup.quantities.push_back({Quantity::sigma_c, SamplePoint::AtAxis, StressComponent::SigmaZ,
                              oracles::cattaneo_mindlin_pressure(exact, 0.0) / exact.p_mean,
                              std::nullopt});
  return setup;
}

}  // namespace cs::suites::problems

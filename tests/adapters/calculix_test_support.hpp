#pragma once
// Models for the CalculiX adapter tests, built from the solver's mesh helpers.

#include <algorithm>
#include <string>
#include <vector>

#include "adapters/calculix/calculix_options.hpp"
#include "oracles/mcewen.hpp"
#include "solver/mesh/indenter.hpp"
#include "solver/mesh/mesh_merge.hpp"
#include "solver/mesh/structured_block.hpp"
#include "solver/model.hpp"

namespace cs::adapters::calculix::test {

inline solver::Mesh block_mesh(solver::ElementType type, double x0, double z0, double width,
                               double height, int nx, int nz, const std::string& body) {
  solver::BlockSpec spec;
  spec.type = type;
  spec.origin = Eigen::Vector2d(x0, z0);
  spec.size = Eigen::Vector2d(width, height);
  spec.nx = nx;
  spec.nz = nz;
  spec.body_name = body;
  return solver::make_block(spec);
}

/// The two-body contact patch test: a block [0, a] x [0, h] (nx x nz elements, E, nu) pressed
/// by a uniform pressure p on z = h onto a stiff indenter [0, a] x [-h/2, 0] (indenter_nx
/// elements across, E ratio 1e6) whose back face z = -h/2 is held in z; both bodies are held
/// in x on x = 0 (symmetry, the axis in axisymmetry) and free to expand laterally. Exact: the
/// uniform stress sigma_z = -p, sigma_x = tau = 0 (sigma_y = -nu p in plane strain,
/// sigma_theta = 0 in axisymmetry) and the contact pressure p.
struct PatchSpec {
  solver::ElementType type = solver::ElementType::Q4;
  solver::AnalysisType analysis = solver::AnalysisType::PlaneStrain;
  int nx = 4;
  int nz = 4;
  int indenter_nx = 3;  ///< != nx: non-matching nodes
  double a = 1.0;
  double h = 1.0;
  double E = 1000.0;
  double nu = 0.3;
  double p = 1.0;
  double E_ratio = 1e6;
};

inline solver::Model patch_model(const PatchSpec& s) {
  using solver::Component;
  using solver::NodeSelection;
  solver::Model model;
  model.mesh =
      solver::merge_bodies({block_mesh(s.type, 0.0, 0.0, s.a, s.h, s.nx, s.nz, "block"),
                            block_mesh(s.type, 0.0, -0.5 * s.h, s.a, 0.5 * s.h, s.indenter_nx,
                                       std::max(1, s.indenter_nx / 2), "indenter")});
  model.analysis = s.analysis;
  model.materials = {{s.E, s.nu}, {s.E * s.E_ratio, s.nu}};
  model.fix(NodeSelection::node_set("block.left"), Component::X);
  model.fix(NodeSelection::node_set("indenter.left"), Component::X);
  model.fix(NodeSelection::node_set("indenter.bottom"), Component::Z);
  model.loads.add_pressure("block.top", s.p);
  return model;
}

inline solver::ContactPair patch_pair() {
  return {"block.bottom", solver::TargetSurface{"indenter.top"}};
}

/// Linear penalty options with K = fkn E / h_elem (h_elem = h / nz, our penalty law) and
/// sigma_inf = 0.25 % p (CalculiX's advice).
inline CalculixOptions penalty_options(const PatchSpec& s, CcxContactType type, double fkn) {
  CalculixOptions options;
  options.contact = type;
  options.behavior = CcxPressureOverclosure::Linear;
  options.penalty_K = fkn * s.E / (s.h / s.nz);
  options.tension_sigma_inf = 0.0025 * s.p;
  options.time_limit_seconds = 60.0;
  return options;
}

/// Plane-strain Hertz contact (the study's H_p): a block [0, 4a] x [0, 4a] of n x n elements
/// loaded by McEwen's exact tractions (study Eqs. 11-12) on z = 4a and x = 4a, symmetric about
/// x = 0, held vertically only by a stiff cylinder of radius R = pi E a / (8 (1 - nu^2) p)
/// (Eq. 16; E ratio 1e6, back face fixed) whose surface nodes line up with the block's.
/// Exact: contact half-width a, -sigma_z(0, 0) / p = 4 / pi, contact force a p (half model).
struct HertzSpec {
  solver::ElementType type = solver::ElementType::Q4;
  int n = 32;
  double a = 1.0;
  double E = 1000.0;
  double nu = 0.3;
  double p = 1.0;
  double R() const { return 3.14159265358979323846 * E * a / (8.0 * (1.0 - nu * nu) * p); }
};

inline solver::Model hertz_model(const HertzSpec& s) {
  using solver::Component;
  using solver::NodeSelection;
  const double L = 4.0 * s.a;
  solver::IndenterSpec ind;
  ind.type = s.type;
  ind.profile = solver::circle_profile(s.R(), 2.0 * s.a);
  for (int i = 0; i <= s.n / 2; ++i)
    ind.surface_x.push_back(2.0 * s.a * i / (s.n / 2));
  ind.height = s.a;
  ind.n_rows = s.n / 4;
  solver::Model model;
  model.mesh = solver::merge_bodies(
      {block_mesh(s.type, 0.0, 0.0, L, L, s.n, s.n, "block"), solver::make_indenter(ind)});
  model.materials = {{s.E, s.nu}, {s.E * 1e6, s.nu}};
  model.fix(NodeSelection::node_set("block.left"), Component::X);
  model.fix(NodeSelection::node_set("indenter.left"), Component::X);
  model.fix(NodeSelection::node_set("indenter.back"), Component::X);
  model.fix(NodeSelection::node_set("indenter.back"), Component::Z);
  const oracles::McEwenLoad load{s.a, s.p};
  model.loads.add_traction("block.top", [load](const Eigen::Vector2d& x) {
    const oracles::PlaneStress st = oracles::mcewen_stress(load, {x.x(), x.y()});
    return Eigen::Vector2d(st.tau_xz, st.sigma_z);  // outward normal +z
  });
  model.loads.add_traction("block.right", [load](const Eigen::Vector2d& x) {
    const oracles::PlaneStress st = oracles::mcewen_stress(load, {x.x(), x.y()});
    return Eigen::Vector2d(st.sigma_x, st.tau_xz);  // outward normal +x
  });
  return model;
}

inline solver::ContactPair hertz_pair() {
  return {"block.bottom", solver::TargetSurface{"indenter.contact"}};
}

}  // namespace cs::adapters::calculix::test

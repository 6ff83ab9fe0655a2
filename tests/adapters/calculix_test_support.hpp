#pragma once
// Models for the CalculiX adapter tests, built from the solver's mesh helpers.

#include <algorithm>
#include <string>
#include <vector>

#include "adapters/calculix/calculix_options.hpp"
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

}  // namespace cs::adapters::calculix::test

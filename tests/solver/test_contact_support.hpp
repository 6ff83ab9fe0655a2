#pragma once
// Models shared by the contact tests (tests/solver/test_contact_*.cpp): blocks pressed onto a
// rigid or a meshed target, built with the mesh layer's generators and the FE core's Model.
//
// Frame as in the study: z points into the indented block, whose contact surface is z = 0; a
// meshed indenter occupies z < 0, its back face fixed.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "oracles/mcewen.hpp"
#include "solver/contact/contact_analysis.hpp"
#include "solver/mesh/indenter.hpp"
#include "solver/mesh/mesh_merge.hpp"
#include "solver/mesh/structured_block.hpp"
#include "solver/model.hpp"

namespace cs::solver::contact_test {

/// A block [0, width] x [0, height] of nx x nz elements named `body`.
inline Mesh block_mesh(ElementType type, double x0, double z0, double width, double height, int nx,
                       int nz, const std::string& body) {
  BlockSpec spec;
  spec.type = type;
  spec.origin = Eigen::Vector2d(x0, z0);
  spec.size = Eigen::Vector2d(width, height);
  spec.nx = nx;
  spec.nz = nz;
  spec.body_name = body;
  return make_block(spec);
}

/// The contact patch test: a block [0, a] x [0, h] (nx x nz elements) pressed by the uniform
/// pressure p on its top z = h onto a flat target at z = 0, held horizontally by symmetry on
/// x = 0 and vertically only by the contact. With indenter_nx > 0 the target is a meshed
/// indenter [0, a] x [-h/2, 0] (indenter_nx x max(1, indenter_nx / 2) elements, E ratio 1e6,
/// back face on rollers so that it too is free to expand laterally); otherwise a rigid plane.
struct PatchSpec {
  ElementType type = ElementType::Q4;
  AnalysisType analysis = AnalysisType::PlaneStrain;
  int nx = 4;
  int nz = 4;
  int indenter_nx = 0;  ///< 0: rigid plane
  double a = 1.0;
  double h = 1.0;
  double E = 1000.0;
  double nu = 0.3;
  double p = 1.0;
  double E_ratio = 1e6;
  /// The study's own set-up instead: the block on rollers at z = h, the meshed indenter loaded
  /// by p on its back face and held only by the contact.
  bool loaded_indenter = false;
};

inline Model patch_model(const PatchSpec& s) {
  std::vector<Mesh> parts{block_mesh(s.type, 0.0, 0.0, s.a, s.h, s.nx, s.nz, "block")};
  if (s.indenter_nx > 0) {
    parts.push_back(block_mesh(s.type, 0.0, -0.5 * s.h, s.a, 0.5 * s.h, s.indenter_nx,
                               std::max(1, s.indenter_nx / 2), "indenter"));
  }
  Model model;
  model.mesh = merge_bodies(parts);
  model.analysis = s.analysis;
  model.materials.push_back({s.E, s.nu});
  model.fix(NodeSelection::node_set("block.left"), Component::X);
  if (s.loaded_indenter) {
    model.fix(NodeSelection::node_set("block.top"), Component::Z);
  } else {
    model.loads.add_pressure("block.top", s.p);
  }
  if (s.indenter_nx > 0) {
    model.materials.push_back({s.E * s.E_ratio, s.nu});
    model.fix(NodeSelection::node_set("indenter.left"), Component::X);
    if (s.loaded_indenter) {
      model.loads.add_pressure("indenter.bottom", s.p);
    } else {
      model.fix(NodeSelection::node_set("indenter.bottom"), Component::Z);
    }
  }
  return model;
}

inline ContactPair patch_pair(const PatchSpec& s) {
  if (s.indenter_nx > 0)
    return {"block.bottom", TargetSurface{"indenter.top"}};
  return {"block.bottom", RigidPlane{{0.0, 0.0}, {0.0, 1.0}}};
}

/// Plane-strain Hertz contact (the study's H_p): a block [0, 4a] x [0, 4a] of n x n elements
/// loaded by McEwen's exact tractions on z = 4a and x = 4a (study Eqs. 11-12), symmetric about
/// x = 0, held vertically only by a cylinder of radius R = pi E a / (8 (1 - nu^2) p) (Eq. 16)
/// touching at x = 0: rigid, or meshed (a circle segment of half-width 2a and height a, nodes
/// at the block's surface x positions, E ratio 1e6, back face fixed).
struct HertzSpec {
  ElementType type = ElementType::Q4;
  int n = 32;  ///< the study's medium mesh (1024 elements)
  bool meshed_indenter = false;
  double a = 1.0;
  double E = 1000.0;
  double nu = 0.3;
  double p = 1.0;  ///< mean pressure P / (2a); p / E = 1e-3
  double E_ratio = 1e6;
  double R() const { return 3.14159265358979323846 * E * a / (8.0 * (1.0 - nu * nu) * p); }
};

inline Model hertz_model(const HertzSpec& s) {
  const double L = 4.0 * s.a;
  std::vector<Mesh> parts{block_mesh(s.type, 0.0, 0.0, L, L, s.n, s.n, "block")};
  if (s.meshed_indenter) {
    IndenterSpec ind;
    ind.type = s.type;
    ind.profile = circle_profile(s.R(), 2.0 * s.a);
    for (int i = 0; i <= s.n / 2; ++i)
      ind.surface_x.push_back(2.0 * s.a * i / (s.n / 2));
    ind.height = s.a;
    ind.n_rows = s.n / 4;
    parts.push_back(make_indenter(ind));
  }
  Model model;
  model.mesh = merge_bodies(parts);
  model.analysis = AnalysisType::PlaneStrain;
  model.materials.push_back({s.E, s.nu});
  model.fix(NodeSelection::node_set("block.left"), Component::X);
  const oracles::McEwenLoad load{s.a, s.p};
  model.loads.add_traction("block.top", [load](const Eigen::Vector2d& x) {
    const oracles::PlaneStress st = oracles::mcewen_stress(load, {x.x(), x.y()});
    return Eigen::Vector2d(st.tau_xz, st.sigma_z);  // outward normal +z
  });
  model.loads.add_traction("block.right", [load](const Eigen::Vector2d& x) {
    const oracles::PlaneStress st = oracles::mcewen_stress(load, {x.x(), x.y()});
    return Eigen::Vector2d(st.sigma_x, st.tau_xz);  // outward normal +x
  });
  if (s.meshed_indenter) {
    model.materials.push_back({s.E * s.E_ratio, s.nu});
    model.fix(NodeSelection::node_set("indenter.left"), Component::X);
    model.fix(NodeSelection::node_set("indenter.back"), Component::X);
    model.fix(NodeSelection::node_set("indenter.back"), Component::Z);
  }
  return model;
}

inline ContactPair hertz_pair(const HertzSpec& s) {
  if (s.meshed_indenter)
    return {"block.bottom", TargetSurface{"indenter.contact"}};
  return {"block.bottom", RigidCircle{{0.0, -s.R()}, s.R()}};
}

/// The settings of one discretization x algorithm.
inline ContactSettings settings(ContactDiscretization d, ContactAlgorithm a) {
  ContactSettings s;
  s.discretization = d;
  s.algorithm = a;
  return s;
}

/// The largest |pressure / p - 1| over the closed nodes, and the number of open nodes.
struct PressureDeviation {
  double max_relative = 0.0;
  int n_open = 0;
};

inline PressureDeviation pressure_deviation(const ContactResult& r, double p) {
  PressureDeviation d;
  for (const ContactNodeResult& n : r.nodes) {
    if (!n.closed) {
      ++d.n_open;
      continue;
    }
    d.max_relative = std::max(d.max_relative, std::abs(n.pressure / p - 1.0));
  }
  return d;
}

}  // namespace cs::solver::contact_test

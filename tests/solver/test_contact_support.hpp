#pragma once
// Models shared by the contact tests (tests/solver/test_contact_*.cpp): blocks pressed onto a
// rigid or a meshed target, built with the mesh layer's generators and the FE core's Model.
//
// Frame as in the study: z points into the indented block, whose contact surface is z = 0; a
// meshed indenter occupies z < 0, its back face fixed.

#include <cmath>
#include <memory>
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

/// The loads of a frictional test model, read by its load and support callables whenever the
/// solver evaluates them: a load step only changes these numbers.
struct FrictionLoad {
  double p = 0.0;          ///< normal pressure (patch) or its resultant's scale (Cattaneo-Mindlin)
  double tau_top = 0.0;    ///< shear traction on the loaded body's far face (+x)
  double tau_sides = 0.0;  ///< shear traction of the uniform shear state on the sides
  double top_ux = 0.0;     ///< prescribed u_x of the block's top (sliding support), plus eps_x x
};

/// The frictional contact patch test: a block [0, a] x [0, h] ("block", nx x nz elements) on a
/// base [0, a] x [-h, 0] ("base", base_nx x nz) of the same material; the block's bottom is the
/// contact surface, the base's top its target. Supports and loads make the exact solution the
/// uniform stress sigma_z = -p, tau_xz = tau (sigma_x = 0), whose displacements are linear, so
/// that the FE space holds it (between non-matching meshes too, with mortar):
///   - base bottom z = -h: u_z = 0 and u_x = eps_x x, eps_x = nu (1 + nu) p / E (plane strain,
///     the lateral expansion under p);
///   - block top: the traction (tau_top, -p); with `sliding_support` its u_x is prescribed to
///     eps_x x + top_ux instead (a support that can drive the block into sliding);
///   - the sides of both bodies: (0, -tau_sides) on x = 0 and (0, +tau_sides) on x = a.
/// The shear transmitted along t = +x is tau; the block's x position is held by friction alone
/// unless the support slides it.
struct FrictionPatchSpec {
  ElementType type = ElementType::Q4;
  int nx = 4;
  int nz = 4;
  int base_nx = 4;
  double a = 1.0;
  double h = 1.0;
  double E = 1000.0;
  double nu = 0.3;
  bool sliding_support = false;
  double shear_modulus() const { return E / (2.0 * (1.0 + nu)); }
  double eps_x(double p) const { return nu * (1.0 + nu) * p / E; }
};

inline Model friction_patch_model(const FrictionPatchSpec& s,
                                  const std::shared_ptr<const FrictionLoad>& load) {
  std::vector<Mesh> parts{block_mesh(s.type, 0.0, 0.0, s.a, s.h, s.nx, s.nz, "block"),
                          block_mesh(s.type, 0.0, -s.h, s.a, s.h, s.base_nx, s.nz, "base")};
  Model model;
  model.mesh = merge_bodies(parts);
  model.analysis = AnalysisType::PlaneStrain;
  model.materials.push_back({s.E, s.nu});
  model.materials.push_back({s.E, s.nu});
  model.fix(NodeSelection::node_set("base.bottom"), Component::Z);
  model.prescribe(NodeSelection::node_set("base.bottom"), Component::X,
                  [s, load](const Eigen::Vector2d& x) { return s.eps_x(load->p) * x.x(); });
  if (s.sliding_support) {
    model.prescribe(
        NodeSelection::node_set("block.top"), Component::X,
        [s, load](const Eigen::Vector2d& x) { return s.eps_x(load->p) * x.x() + load->top_ux; });
  }
  model.loads.add_traction("block.top", [load](const Eigen::Vector2d&) {
    return Eigen::Vector2d(load->tau_top, -load->p);
  });
  for (const char* body : {"block", "base"}) {
    model.loads.add_traction(std::string(body) + ".left", [load](const Eigen::Vector2d&) {
      return Eigen::Vector2d(0.0, -load->tau_sides);
    });
    model.loads.add_traction(std::string(body) + ".right", [load](const Eigen::Vector2d&) {
      return Eigen::Vector2d(0.0, load->tau_sides);
    });
  }
  return model;
}

inline ContactPair friction_patch_pair() {
  return {"block.bottom", TargetSurface{"base.top"}};
}

/// Cattaneo-Mindlin in plane strain, two bodies of the same material: a block [-L, L] x [0, L]
/// ("block", n_x x n_x / 2 elements; its bottom z = 0 the contact surface) pressed by a cylinder
/// of radius R ("cylinder": [-L, L] wide, from its contact surface z = -(R - sqrt(R^2 - x^2))
/// to its back z = -L; n_x x n_x / 4 elements; its contact surface the target). Both bodies
/// carry on their far boundaries the tractions of the same uniform stress state (sigma_z = -p,
/// tau_xz = tau_top): the block (tau_top, -p) on its top, the cylinder (-tau_top, p) on its back,
/// and both the couple (0, -+tau_sides) on their sides (so that the tangential load adds no
/// moment about the contact). The loads are self-equilibrated; a statically determinate and
/// symmetric support (the cylinder's back centre held in x, its back corners in z) only removes
/// the rigid-body modes, so both bodies deform alike, as two half-spaces would, and the assembly
/// does not turn (small-sliding rows with an initial gap are not invariant under a rigid
/// rotation: an asymmetric support tilts the shear at the contact edges by ~0.01 p0). Normal load
/// P = 2 L p, tangential Q = 2 L tau_top (per unit thickness).
struct MindlinSpec {
  ElementType type = ElementType::Q4;
  int n_x = 64;       ///< elements across 2L (element size 2L / n_x at the contact); n_x % 4 == 0
  double L = 4.0;     ///< half-width and depth of both bodies
  double R = 100.0;   ///< cylinder radius
  double E = 1000.0;  ///< both bodies
  double nu = 0.3;
  /// Hertz's half-width of two equal bodies, a^2 = 8 P R (1 - nu^2) / (pi E).
  double hertz_a(double P) const {
    return std::sqrt(8.0 * P * R * (1.0 - nu * nu) / (3.14159265358979323846 * E));
  }
};

inline Mesh mindlin_cylinder(const MindlinSpec& s) {
  MappedBlockSpec cyl;
  cyl.type = s.type;
  for (int i = 0; i <= s.n_x; ++i)
    cyl.u.push_back(static_cast<double>(i) / s.n_x);
  for (int j = 0; j <= s.n_x / 4; ++j)
    cyl.v.push_back(static_cast<double>(j) / (s.n_x / 4));
  const double L = s.L, R = s.R;
  cyl.map = [L, R](double u, double v) {
    const double x = -L + 2.0 * L * u;
    const double surface = -(R - std::sqrt(R * R - x * x));
    return Eigen::Vector2d(x, -L + v * (L + surface));
  };
  cyl.body_name = "cylinder";
  return make_mapped_block(cyl);
}

inline Model mindlin_model(const MindlinSpec& s, const std::shared_ptr<const FrictionLoad>& load) {
  std::vector<Mesh> parts{block_mesh(s.type, -s.L, 0.0, 2.0 * s.L, s.L, s.n_x, s.n_x / 2, "block"),
                          mindlin_cylinder(s)};
  Model model;
  model.mesh = merge_bodies(parts);
  model.analysis = AnalysisType::PlaneStrain;
  model.materials.push_back({s.E, s.nu});
  model.materials.push_back({s.E, s.nu});
  const std::vector<int>& back = model.mesh.node_sets.at("cylinder.bottom");  // sorted by x
  const int centre = back[back.size() / 2];
  model.fix(NodeSelection::list({centre}, "cylinder back centre"), Component::X);
  model.fix(NodeSelection::list({back.front(), back.back()}, "cylinder back corners"),
            Component::Z);
  model.loads.add_traction("block.top", [load](const Eigen::Vector2d&) {
    return Eigen::Vector2d(load->tau_top, -load->p);
  });
  model.loads.add_traction("cylinder.bottom", [load](const Eigen::Vector2d&) {
    return Eigen::Vector2d(-load->tau_top, load->p);
  });
  for (const char* body : {"block", "cylinder"}) {
    model.loads.add_traction(std::string(body) + ".left", [load](const Eigen::Vector2d&) {
      return Eigen::Vector2d(0.0, -load->tau_sides);
    });
    model.loads.add_traction(std::string(body) + ".right", [load](const Eigen::Vector2d&) {
      return Eigen::Vector2d(0.0, load->tau_sides);
    });
  }
  return model;
}

inline ContactPair mindlin_pair() {
  return {"block.bottom", TargetSurface{"cylinder.top"}};
}

/// The settings of a frictional method: the study's PM, AL, LMP, PLM.
inline ContactSettings friction_settings(ContactDiscretization d, ContactAlgorithm a, double mu,
                                         TangentialEnforcement t = TangentialEnforcement::Penalty) {
  ContactSettings s;
  s.discretization = d;
  s.algorithm = a;
  s.mu = mu;
  s.tangential = t;
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

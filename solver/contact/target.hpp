#pragma once
// The target of a contact pair: the meshed surface of another body (the study's stiff indenter,
// E ratio 1e6) or a rigid analytic profile. Both answer the same question for a point x of the
// contact surface: the signed gap to the target, the target's normal there, and which target
// nodes carry the closest point (none for a rigid profile).
//
// Small sliding: projections are computed once, in the reference configuration; the gap of the
// displaced configuration is linearized as
//   g = g0 + n . (u(x) - sum_i N_i u_i),
// with n the target's unit normal at the closest point (out of the target, towards the contact
// side) and N_i the target segment's shape functions at the closest point.

#include <array>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "solver/contact/contact_surface.hpp"
#include "solver/contact/rigid_profile.hpp"
#include "solver/model.hpp"

namespace cs::solver {

/// Two lengths of a contact geometry within this fraction of each other (or of the element
/// depth) are a tie (a point exactly at the pinball radius, a point equally far from two target
/// segments): decided by a fixed rule, never by round-off, which would make the result depend on
/// the units (tests/suites/test_scaling_invariance.cpp).
inline constexpr double kGeometricTie = 1e-9;

/// Names the edge set of a meshed body that serves as the target (e.g. "indenter.bottom").
struct TargetSurface {
  std::string edge_set;
};

/// What a contact pair names as its target: a meshed surface or a rigid profile.
using TargetSpec = std::variant<TargetSurface, RigidProfile>;

/// `spec` with its lengths times L (a rigid profile's, see scale_lengths(RigidProfile); a target
/// surface is a set name and scales with its mesh).
TargetSpec scale_lengths(const TargetSpec& spec, double L);

/// A meshed target: the segments of the target body's edge set. Its normals point out of the
/// target body.
struct MeshedTarget {
  ContactSurface surface;
};

/// A target ready for projections.
using ContactTarget = std::variant<MeshedTarget, RigidProfile>;

/// Builds the target named by `spec` on `model`. Throws ContactError for an unknown or empty
/// target edge set or an invalid rigid profile.
ContactTarget make_target(const Model& model, const TargetSpec& spec);

/// The closest point of the target to a contact point.
struct TargetPoint {
  double gap = 0.0;                   ///< signed distance, > 0 open, < 0 penetrating
  Eigen::Vector2d normal{0.0, 1.0};   ///< unit, out of the target towards the contact side
  Eigen::Vector2d closest{0.0, 0.0};  ///< the closest target point
  int n_master = 0;                   ///< nodes carrying it (0 for a rigid profile)
  std::array<int, 3> master_nodes{-1, -1, -1};  ///< target node indices
  std::array<double, 3> master_weights{};       ///< shape function values N_i at the point
};

/// Projects x onto the target (closest point). On a meshed target, a point beyond the end of the
/// target surface (or in the wedge outside a convex corner between segments) is closest to the
/// corner node; its normal is then the direction from that node to x.
TargetPoint project(const ContactTarget& target, const Eigen::Vector2d& x);

/// The points where mortar integration cuts a contact segment: the nodes of a meshed target,
/// the kinks of a rigid profile.
std::vector<Eigen::Vector2d> target_breakpoints(const ContactTarget& target);

/// "target surface 'indenter.bottom'" or the rigid profile's description.
std::string describe(const ContactTarget& target);

}  // namespace cs::solver

#pragma once
// Rigid analytic target profiles: a plane, a circle (cylinder in plane strain, sphere in
// axisymmetry), a flat punch with rounded edges and a flat punch with sharp corners.
//
// Each profile is the boundary of a rigid region. For a point x, closest_point() gives the
// signed distance to the profile (the gap: > 0 outside the rigid region, < 0 inside), the unit
// normal of the profile at the closest point (pointing out of the rigid region, i.e. the
// direction in which the gap grows) and the closest point itself. Small-sliding contact
// linearizes the gap of a point that moves by u as g(x + u) ~ g(x) + n . u.
//
// The punches are described in a local frame: the face centre c, the unit direction d from the
// punch into the deformable body (the outward normal of the face; the study's (0, 1) with z
// pointing into the indented body) and the face coordinate s = (x - c) . t, t = (d_z, -d_x).
// A punch is symmetric about s = 0 (in axisymmetry, c lies on the axis and s is r).

#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

namespace cs::solver {

/// A rigid half-space: { x : (x - point) . normal < 0 }.
struct RigidPlane {
  Eigen::Vector2d point{0.0, 0.0};   ///< a point of the plane
  Eigen::Vector2d normal{0.0, 1.0};  ///< points out of the rigid side (normalized on use)
};

/// A rigid disk { |x - center| < radius }: a cylinder (plane strain) or a sphere
/// (axisymmetric; the centre must lie on the axis r = 0).
struct RigidCircle {
  Eigen::Vector2d center{0.0, 0.0};
  double radius = 1.0;  ///< R > 0
};

/// A flat punch of face width 2b whose edges are rounded with radius r_e (Steuermann's punch):
/// flat for |s| <= b, quarter circles of radius r_e centred at s = +-b, 1 r_e behind the face,
/// then straight sides at |s| = b + r_e.
struct RoundedFlatPunch {
  Eigen::Vector2d face_center{0.0, 0.0};  ///< c: centre of the flat face
  Eigen::Vector2d direction{0.0, 1.0};    ///< d: from the punch into the body (normalized on use)
  double half_width_b = 1.0;              ///< b > 0: half-width of the flat part
  double edge_radius_re = 1.0;            ///< r_e > 0: edge radius
};

/// A flat punch with sharp corners, face width 2a (Sadowsky / Harding-Sneddon punch).
struct SharpFlatPunch {
  Eigen::Vector2d face_center{0.0, 0.0};  ///< c: centre of the face
  Eigen::Vector2d direction{0.0, 1.0};    ///< d: from the punch into the body (normalized on use)
  double half_width_a = 1.0;              ///< a > 0: half-width of the face
};

/// A rigid analytic target.
using RigidProfile = std::variant<RigidPlane, RigidCircle, RoundedFlatPunch, SharpFlatPunch>;

/// The closest point of a profile to a point, with the signed gap and the profile's normal.
struct ProfilePoint {
  double gap = 0.0;                   ///< signed distance: > 0 outside the rigid region
  Eigen::Vector2d normal{0.0, 1.0};   ///< unit, out of the rigid region, at the closest point
  Eigen::Vector2d closest{0.0, 0.0};  ///< the closest point of the profile
};

/// The signed gap, normal and closest point of the profile for the point `x`.
/// At a sharp corner the normal is the direction from the corner to x (the face normal for a
/// point straight above the face, |s| <= a, including its ends).
ProfilePoint closest_point(const RigidProfile& profile, const Eigen::Vector2d& x);

/// The points of the profile where its curvature jumps (flat-to-arc and arc-to-side points of
/// the rounded punch, the corners of the sharp punch); none for the plane and the circle.
/// Mortar integration cuts contact segments there.
std::vector<Eigen::Vector2d> profile_kinks(const RigidProfile& profile);

/// Throws ContactError unless radii and widths are positive and finite and normals and
/// directions are non-zero and finite.
void validate(const RigidProfile& profile);

/// The profile with every length times L > 0 (points, radii, widths; normals and directions
/// unchanged): the rigid part of a model scaled by solver/model_scaling.hpp. The factor is not
/// validated here (validate(ModelScaling) does).
RigidProfile scale_lengths(const RigidProfile& profile, double L);

/// "rigid plane", "rigid circle R = 2", ... for messages.
std::string describe(const RigidProfile& profile);

}  // namespace cs::solver

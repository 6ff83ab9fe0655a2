#pragma once
// Along which normal a contact constraint measures the gap and transmits the contact force.
//
// The analytic solutions of indentation (Hertz, Steuermann, the flat punch) linearize the
// contact of a shallow indenter with a half-space: the gap and the pressure are taken along the
// half-space's own normal, the vertical of its flat face, at the reference positions. A contact
// constraint along the target's normal instead (the default) also sees the indented surface's
// tangential displacement u_t on a target face inclined by theta to it: the gap changes by
// theta u_t, and the force has a tangential part theta p. Both are first order in the load (u_t
// and theta grow with p/E), so they are absent from the small-strain theory; on the rounded
// edge of a Steuermann punch (theta up to (a - b) / r_e) they lower the peak pressure by about
// 0.1 % at the study's p/E = 1e-3 (S(1)), a floor that refinement cannot remove.

#include <Eigen/Core>

#include "solver/contact/target.hpp"

namespace cs::solver {

enum class GapNormal {
  Target,          ///< the target's normal at the closest point (the default)
  ContactSurface,  ///< the contact surface's own normal (the half-space theory's linearization)
};

/// The gap of `tp` measured along the contact surface's outward unit normal `n_contact`
/// instead of the target's normal: the direction is -n_contact (out of the target, like
/// tp.normal) and the gap is the distance along it to the target's tangent line at the closest
/// point, tp.gap / cos(angle between the normals) (exact for a straight target segment). Where
/// the two normals are more than about 84 degrees apart (cos < 0.1: the surfaces do not face
/// each other, far from any contact) `tp` is returned unchanged.
TargetPoint along_contact_normal(const TargetPoint& tp, const Eigen::Vector2d& n_contact);

/// `tp` unchanged for GapNormal::Target, else along_contact_normal(tp, n_contact).
TargetPoint oriented(const TargetPoint& tp, GapNormal normal, const Eigen::Vector2d& n_contact);

}  // namespace cs::solver

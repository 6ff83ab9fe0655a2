#pragma once
// Mortar (segment-to-segment) contact: one constraint per node a of the contact surface, the
// gap weighted by the node's multiplier basis function and integrated over the surface,
//
//   g_a = int Phi_a g (r) ds / w_a,   w_a = int Phi_a (r) ds,
//   g   = g(x) + n . (u(x) - sum_i N_i u_i)   (the linearized gap at each point x),
//
// MULTIPLIER SPACE: standard Lagrange multipliers on the contact (non-mortar, deformable) side,
// spanning the trace of the contact side's displacement space (linear for Q4, quadratic for
// Q8), in a basis Phi_a >= 0: the hat functions N_a on Q4 sides, the quadratic Bernstein basis on
// Q8 sides (see weighted_gap_constraints in constraint_set.hpp: the Lagrange corner functions
// change sign, which broke the inequality on axisymmetric Q8 surfaces). The contact pressure is
// p_h = sum_a p_a Phi_a with p_a = lambda_a / w_a, the value reported per node (p_h itself at a
// corner; at a Q8 mid-side node p_h = (p_0 + 2 p_m + p_1) / 4).
//
// Integration is exact for a flat interface: every contact segment is cut where a target node
// (or a kink of a rigid profile) projects into it, and each piece is integrated with 5 Gauss
// points (degree 9 >= N_a (2) x displacement (2) x r (1)). So a uniform pressure passes
// between non-matching meshes exactly: the contact patch test P' holds to round-off, in plane
// strain and (with the r weight, per radian) in axisymmetry.

#include "solver/contact/constraint_set.hpp"

namespace cs::solver {

/// Gauss points per integration piece of a mortar segment.
inline constexpr int kMortarGaussPoints = 5;

/// The mortar rows of `surface` against `target`; B has n_dofs columns.
ConstraintSet mortar_constraints(const ContactSurface& surface, const ContactTarget& target,
                                 int n_dofs, GapNormal normal = GapNormal::Target);

/// The parameters in (-1, 1) of segment k of `surface` at which `points` project (closest
/// point), sorted and unique: where mortar integration cuts the segment.
std::vector<double> mortar_cuts(const ContactSurface& surface, int k,
                                const std::vector<Eigen::Vector2d>& points);

}  // namespace cs::solver

#pragma once
// ss, surface-to-surface: the constraint imposed at the Gauss points of the contact segments
// (2 per Q4 side, 3 per Q8 side: the element's own edge rule), like the commercial
// surface-based contact elements with Gauss-point detection.
//
// Penalty and augmented Lagrangian: one row per Gauss point q of segment k,
//   g_q = g(x_q) + n . (sum_b N_b(t_q) u_b - sum_i N_i u_i),   weight w_q = W_q |x'(t_q)| (r_q),
// each with its own penalty FKN (E / h) w_q and its own active flag.
// Lagrange multiplier and MPC: Gauss-point multipliers would over-constrain the surface (more
// rows than contact DOFs), so the same Gauss points integrate one weighted gap per node,
//   g_a = sum_q Phi_a(t_q) w_q g_q / sum_q Phi_a(t_q) w_q,
// with nodal multipliers (no segmentation at target nodes: that is what mortar adds) and the
// multiplier basis Phi_a >= 0 of mortar (N_a on Q4 sides, Bernstein on Q8 sides).

#include "solver/contact/constraint_set.hpp"

namespace cs::solver {

/// Which rows surface-to-surface produces.
enum class SurfaceToSurfaceRows {
  GaussPoints,        ///< one row per Gauss point (penalty, augmented Lagrangian)
  NodalWeightedGaps,  ///< one Gauss-integrated weighted gap per node (LM, MPC)
};

/// The number of Gauss points per contact segment: 2 (Q4 sides) or 3 (Q8 sides).
int surface_gauss_points(ElementType type);

/// The surface-to-surface rows of `surface` against `target`; B has n_dofs columns.
ConstraintSet surface_to_surface_constraints(const ContactSurface& surface,
                                             const ContactTarget& target, int n_dofs,
                                             SurfaceToSurfaceRows rows,
                                             GapNormal normal = GapNormal::Target);

}  // namespace cs::solver

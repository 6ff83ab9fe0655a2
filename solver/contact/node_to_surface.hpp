#pragma once
// ns, node-to-surface (collocation): one constraint per node of the contact surface, its gap
// measured at the node,
//
//   g_a = g(x_a) + n . (u_a - sum_i N_i u_i),
//
// n the target normal at the node's closest target point. The row's weight is the node's
// consistent tributary measure w_a = int N_a (r) ds, so that a uniform pressure p is the
// consistent nodal force p w_a (for Q8 sides 1/6, 2/3, 1/6 of p L, not the lumped 1/4, 1/2,
// 1/4) and a penalty k = FKN (E / h) w_a reproduces a uniform pressure exactly. (The corner node
// on the axis of an axisymmetric Q8 surface, whose w_a is 0, is weighted by int |N_a| r ds.)

#include "solver/contact/constraint_set.hpp"

namespace cs::solver {

/// The node-to-surface rows of `surface` against `target`; B has n_dofs columns.
ConstraintSet node_to_surface_constraints(const ContactSurface& surface,
                                          const ContactTarget& target, int n_dofs,
                                          GapNormal normal = GapNormal::Target);

}  // namespace cs::solver

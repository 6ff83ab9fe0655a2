#include "solver/contact/node_to_surface.hpp"

namespace cs::solver {

ConstraintSet node_to_surface_constraints(const ContactSurface& surface,
                                          const ContactTarget& target, int n_dofs,
                                          GapNormal normal) {
  ConstraintSet set;
  set.nodes = contact_nodes(surface);
  set.nodal = true;
  set.weighted = false;
  const int m = static_cast<int>(set.nodes.size());
  set.rows.resize(m);
  set.g0.resize(m);
  std::vector<Eigen::Triplet<double>> triplets, slip_triplets;
  for (int i = 0; i < m; ++i) {
    const ContactNode& n = set.nodes[i];
    const TargetPoint tp = oriented(project(target, n.position), normal, n.normal);
    ContactConstraint& r = set.rows[i];
    r.position = n.position;
    r.node = i;
    r.n_shares = 1;
    r.share_nodes[0] = i;
    r.shares[0] = 1.0;
    r.weight_w = n.degenerate() ? n.weight_abs : n.weight_w;
    r.stiffness_per_area = n.stiffness_per_area;
    r.depth_h = n.depth_h;
    r.normal = tp.normal;
    set.g0[i] = tp.gap;
    add_gap_triplets(i, 1.0, tp, 1, {n.node, -1, -1}, {1.0, 0.0, 0.0}, triplets);
    add_direction_triplets(i, 1.0, target_tangent(tp), tp, 1, {n.node, -1, -1}, {1.0, 0.0, 0.0},
                           slip_triplets);
  }
  set.B = assemble_rows(m, n_dofs, triplets);
  set.T = assemble_rows(m, n_dofs, slip_triplets);
  set.s0 = Eigen::VectorXd::Zero(m);
  return set;
}

}  // namespace cs::solver

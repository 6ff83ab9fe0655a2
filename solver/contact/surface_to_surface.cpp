#include "solver/contact/surface_to_surface.hpp"

#include "solver/elements/gauss_rule.hpp"

namespace cs::solver {

int surface_gauss_points(ElementType type) {
  return type == ElementType::Q4 ? 2 : 3;
}

namespace {

ConstraintSet gauss_point_constraints(const ContactSurface& surface, const ContactTarget& target,
                                      int n_dofs, GapNormal normal) {
  ConstraintSet set;
  set.nodes = contact_nodes(surface);
  set.nodal = false;
  set.weighted = false;
  const GaussRule1D& rule = gauss_rule_1d(surface_gauss_points(surface.element_type()));
  std::vector<Eigen::Triplet<double>> triplets, slip_triplets;
  std::vector<double> g0;
  for (int k = 0; k < surface.n_segments(); ++k) {
    const ContactSegment& seg = surface.segment(k);
    for (int q = 0; q < rule.size(); ++q) {
      const double t = rule.points[q];
      const Eigen::Vector2d x = surface.point(k, t);
      const TargetPoint tp = oriented(project(target, x), normal, surface.normal(k, t));
      const SideShapeValues sv = surface.shape(k, t);
      ContactConstraint r;
      r.position = x;
      r.node = -1;
      r.n_shares = seg.n_nodes;
      for (int a = 0; a < seg.n_nodes; ++a) {
        r.share_nodes[a] = find_contact_node(set.nodes, seg.nodes[a]);
        r.shares[a] = sv.N[a];
      }
      r.weight_w = rule.weights[q] * surface.measure(k, t);
      r.stiffness_per_area = seg.youngs_modulus_E / seg.depth_h;
      r.depth_h = seg.depth_h;
      r.normal = tp.normal;
      const int row = static_cast<int>(set.rows.size());
      const std::array<double, 3> N{sv.N[0], sv.N[1], sv.N[2]};
      add_gap_triplets(row, 1.0, tp, seg.n_nodes, seg.nodes, N, triplets);
      add_direction_triplets(row, 1.0, target_tangent(tp), tp, seg.n_nodes, seg.nodes, N,
                             slip_triplets);
      set.rows.push_back(r);
      g0.push_back(tp.gap);
    }
  }
  set.g0 = Eigen::Map<const Eigen::VectorXd>(g0.data(), static_cast<Eigen::Index>(g0.size()));
  set.B = assemble_rows(set.n_rows(), n_dofs, triplets);
  set.T = assemble_rows(set.n_rows(), n_dofs, slip_triplets);
  set.s0 = Eigen::VectorXd::Zero(set.n_rows());
  return set;
}

}  // namespace

ConstraintSet surface_to_surface_constraints(const ContactSurface& surface,
                                             const ContactTarget& target, int n_dofs,
                                             SurfaceToSurfaceRows rows, GapNormal normal) {
  if (rows == SurfaceToSurfaceRows::GaussPoints) {
    return gauss_point_constraints(surface, target, n_dofs, normal);
  }
  return weighted_gap_constraints(
      surface, target, n_dofs, surface_gauss_points(surface.element_type()),
      [](int) { return std::vector<double>{}; }, normal);
}

}  // namespace cs::solver

#include "solver/contact/constraint_set.hpp"

#include <algorithm>
#include <cmath>

#include "solver/elements/gauss_rule.hpp"

namespace cs::solver {

namespace {

/// Gauss points per segment for tributary weights: exact for N_a (degree 2) x r (degree 1) x
/// |x'| (degree 1 on a curved Q8 side) and close for other curved sides.
constexpr int kWeightPoints = 5;

/// The multiplier basis Phi_a of a segment's nodes from its side shape functions N (see
/// constraint_set.hpp): N itself on a Q4 side; on a Q8 side the quadratic Bernstein basis,
///   Phi_c = N_c + N_m / 4 (corners),   Phi_m = N_m / 2 (mid-side).
std::array<double, 3> multiplier_basis(int n_nodes, const std::array<double, 3>& N) {
  if (n_nodes != 3)
    return N;
  return {N[0] + 0.25 * N[2], N[1] + 0.25 * N[2], 0.5 * N[2]};
}

}  // namespace

std::vector<ContactNode> contact_nodes(const ContactSurface& surface) {
  std::vector<ContactNode> nodes;
  nodes.reserve(surface.nodes().size());
  for (std::size_t i = 0; i < surface.nodes().size(); ++i) {
    ContactNode n;
    n.node = surface.nodes()[i];
    n.position = surface.node_positions()[i];
    nodes.push_back(n);
  }
  const GaussRule1D& rule = gauss_rule_1d(kWeightPoints);
  for (int k = 0; k < surface.n_segments(); ++k) {
    const ContactSegment& seg = surface.segment(k);
    for (int q = 0; q < rule.size(); ++q) {
      const double t = rule.points[q];
      const double dm = rule.weights[q] * surface.measure(k, t);
      const SideShapeValues sv = surface.shape(k, t);
      for (int a = 0; a < seg.n_nodes; ++a) {
        ContactNode& n = nodes[find_contact_node(nodes, seg.nodes[a])];
        const double abs_w = std::abs(sv.N[a]) * dm;
        n.weight_w += sv.N[a] * dm;
        n.weight_abs += abs_w;
        n.depth_h += abs_w * seg.depth_h;
        n.stiffness_per_area += abs_w * seg.youngs_modulus_E / seg.depth_h;
        n.normal += abs_w * surface.normal(k, t);
      }
    }
  }
  for (ContactNode& n : nodes) {
    n.depth_h /= n.weight_abs;
    n.stiffness_per_area /= n.weight_abs;
    n.normal.normalize();
  }
  // A degenerate node reports the pressure of the segment node with the largest weight.
  for (int k = 0; k < surface.n_segments(); ++k) {
    const ContactSegment& seg = surface.segment(k);
    for (int a = 0; a < seg.n_nodes; ++a) {
      ContactNode& n = nodes[find_contact_node(nodes, seg.nodes[a])];
      if (!n.degenerate() || n.pressure_neighbour >= 0)
        continue;
      // Weights equal to round-off (on a uniform axisymmetric Q8 surface the axis corner's
      // mid-side neighbour and far corner both have h^2/3) are a tie: the nearer node, the mid-side
      // one, takes it in any units.
      int best = -1;
      for (int b = 0; b < seg.n_nodes; ++b) {
        const int j = find_contact_node(nodes, seg.nodes[b]);
        if (b == a || nodes[j].degenerate())
          continue;
        if (best < 0 || nodes[j].weight_w > nodes[best].weight_w * (1.0 + kGeometricTie)) {
          best = j;
        } else if (nodes[j].weight_w >= nodes[best].weight_w * (1.0 - kGeometricTie) &&
                   (nodes[j].position - n.position).norm() <
                       (nodes[best].position - n.position).norm()) {
          best = j;
        }
      }
      n.pressure_neighbour = best;
    }
  }
  return nodes;
}

int find_contact_node(const std::vector<ContactNode>& nodes, int node) {
  const auto it = std::lower_bound(nodes.begin(), nodes.end(), node,
                                   [](const ContactNode& n, int v) { return n.node < v; });
  return it != nodes.end() && it->node == node ? static_cast<int>(it - nodes.begin()) : -1;
}

void add_gap_triplets(int row, double scale, const TargetPoint& tp, int n_slave,
                      const std::array<int, 3>& slave_nodes, const std::array<double, 3>& slave_N,
                      std::vector<Eigen::Triplet<double>>& triplets) {
  add_direction_triplets(row, scale, tp.normal, tp, n_slave, slave_nodes, slave_N, triplets);
}

void add_direction_triplets(int row, double scale, const Eigen::Vector2d& direction,
                            const TargetPoint& tp, int n_slave,
                            const std::array<int, 3>& slave_nodes,
                            const std::array<double, 3>& slave_N,
                            std::vector<Eigen::Triplet<double>>& triplets) {
  for (int b = 0; b < n_slave; ++b) {
    if (slave_N[b] == 0.0)
      continue;
    for (int c = 0; c < 2; ++c) {
      if (direction[c] == 0.0)
        continue;
      triplets.emplace_back(row, 2 * slave_nodes[b] + c, scale * slave_N[b] * direction[c]);
    }
  }
  for (int i = 0; i < tp.n_master; ++i) {
    if (tp.master_weights[i] == 0.0)
      continue;
    for (int c = 0; c < 2; ++c) {
      if (direction[c] == 0.0)
        continue;
      triplets.emplace_back(row, 2 * tp.master_nodes[i] + c,
                            -scale * tp.master_weights[i] * direction[c]);
    }
  }
}

Eigen::SparseMatrix<double, Eigen::RowMajor> assemble_rows(
    int n_rows, int n_dofs, const std::vector<Eigen::Triplet<double>>& triplets) {
  Eigen::SparseMatrix<double, Eigen::RowMajor> B(n_rows, n_dofs);
  B.setFromTriplets(triplets.begin(), triplets.end());
  B.makeCompressed();
  return B;
}

ConstraintSet weighted_gap_constraints(const ContactSurface& surface, const ContactTarget& target,
                                       int n_dofs, int points,
                                       const std::function<std::vector<double>(int)>& cuts,
                                       GapNormal normal) {
  ConstraintSet set;
  set.nodes = contact_nodes(surface);
  set.nodal = true;
  set.weighted = true;
  const int m = static_cast<int>(set.nodes.size());
  std::vector<double> gap_integral(m, 0.0), weight(m, 0.0), weight_abs(m, 0.0);
  std::vector<Eigen::Vector2d> normal_sum(m, Eigen::Vector2d::Zero());
  std::vector<Eigen::Triplet<double>> triplets, slip_triplets;
  const GaussRule1D& rule = gauss_rule_1d(points);
  std::array<int, 3> slave_index{-1, -1, -1};
  for (int k = 0; k < surface.n_segments(); ++k) {
    const ContactSegment& seg = surface.segment(k);
    for (int a = 0; a < seg.n_nodes; ++a)
      slave_index[a] = find_contact_node(set.nodes, seg.nodes[a]);
    std::vector<double> ends = cuts(k);
    ends.insert(ends.begin(), -1.0);
    ends.push_back(1.0);
    for (std::size_t p = 0; p + 1 < ends.size(); ++p) {
      const double half = 0.5 * (ends[p + 1] - ends[p]);
      const double mid = 0.5 * (ends[p + 1] + ends[p]);
      if (!(half > 0.0))
        continue;
      for (int q = 0; q < rule.size(); ++q) {
        const double t = mid + half * rule.points[q];
        const double dm = rule.weights[q] * half * surface.measure(k, t);
        const TargetPoint tp =
            oriented(project(target, surface.point(k, t)), normal, surface.normal(k, t));
        const SideShapeValues sv = surface.shape(k, t);
        std::array<double, 3> N{sv.N[0], sv.N[1], sv.N[2]};
        const std::array<double, 3> phi = multiplier_basis(seg.n_nodes, N);
        for (int a = 0; a < seg.n_nodes; ++a) {
          const int i = slave_index[a];
          const double f = phi[a] * dm;
          gap_integral[i] += f * tp.gap;
          weight[i] += f;
          weight_abs[i] += std::abs(f);
          normal_sum[i] += std::abs(f) * tp.normal;
          add_gap_triplets(i, f, tp, seg.n_nodes, seg.nodes, N, triplets);
          add_direction_triplets(i, f, target_tangent(tp), tp, seg.n_nodes, seg.nodes, N,
                                 slip_triplets);
        }
      }
    }
  }
  set.rows.resize(m);
  set.g0.resize(m);
  std::vector<double> row_weight(m);
  for (int i = 0; i < m; ++i) {
    const ContactNode& n = set.nodes[i];
    ContactConstraint& r = set.rows[i];
    r.position = n.position;
    r.node = i;
    r.n_shares = 1;
    r.share_nodes[0] = i;
    r.shares[0] = 1.0;
    // Weighted rows are normalized by their own quadrature's weight, so that a uniform gap d
    // gives g_a = d exactly (Phi_a >= 0, so w_a > 0 on any surface of positive measure; the
    // int |Phi_a| r ds fallback only guards against a vanishing one).
    row_weight[i] = weight[i] > 0.25 * weight_abs[i] ? weight[i] : weight_abs[i];
    r.weight_w = row_weight[i];
    r.stiffness_per_area = n.stiffness_per_area;
    r.depth_h = n.depth_h;
    r.normal = normal_sum[i].norm() > 0.0 ? normal_sum[i].normalized() : Eigen::Vector2d(0, 1);
    set.g0[i] = gap_integral[i] / row_weight[i];
  }
  std::vector<Eigen::Triplet<double>> scaled;
  scaled.reserve(triplets.size());
  for (const auto& t : triplets)
    scaled.emplace_back(t.row(), t.col(), t.value() / row_weight[t.row()]);
  set.B = assemble_rows(m, n_dofs, scaled);
  scaled.clear();
  for (const auto& t : slip_triplets)
    scaled.emplace_back(t.row(), t.col(), t.value() / row_weight[t.row()]);
  set.T = assemble_rows(m, n_dofs, scaled);
  set.s0 = Eigen::VectorXd::Zero(m);
  return set;
}

}  // namespace cs::solver

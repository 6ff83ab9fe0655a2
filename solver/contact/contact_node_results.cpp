#include "solver/contact/contact_node_results.hpp"

#include <algorithm>
#include <cmath>

namespace cs::solver {

std::vector<ContactNodeResult> node_results(const ConstraintSet& set, const RowState& rows,
                                            const Eigen::VectorXd& node_gap) {
  const int n_nodes = static_cast<int>(set.nodes.size());
  std::vector<ContactNodeResult> nodes(n_nodes);
  std::vector<double> force(n_nodes, 0.0);
  for (int j = 0; j < set.n_rows(); ++j) {
    const ContactConstraint& row = set.rows[j];
    const bool candidate = rows.candidate_of_row[j] >= 0;
    // Closed: active, or a candidate lying on the target (a tie lambda = g = 0 that the active
    // set may resolve either way, e.g. a node that carries no consistent force).
    const bool closed =
        rows.active[j] != 0 || (candidate && std::abs(rows.gap[j]) <= kTouchingGap * row.depth_h);
    for (int s = 0; s < row.n_shares; ++s) {
      const int i = row.share_nodes[s];
      force[i] += row.shares[s] * rows.lambda[j];
      if (row.shares[s] != 0.0) {
        nodes[i].closed = nodes[i].closed || closed;
        nodes[i].candidate = nodes[i].candidate || candidate;
      }
    }
  }
  for (int i = 0; i < n_nodes; ++i) {
    const ContactNode& n = set.nodes[i];
    ContactNodeResult& r = nodes[i];
    r.node = n.node;
    r.position = n.position;
    r.gap = node_gap[i];
    r.penetration = std::max(0.0, -r.gap);
    r.force = set.weighted ? rows.lambda[i] : force[i];
    if (set.weighted) {
      r.pressure = rows.lambda[i] / set.rows[i].weight_w;  // the coefficient p_a
    } else if (!n.degenerate()) {
      r.pressure = force[i] / n.weight_w;
    }
  }
  if (!set.weighted) {
    for (int i = 0; i < n_nodes; ++i) {
      const int nb = set.nodes[i].pressure_neighbour;
      if (set.nodes[i].degenerate() && nb >= 0)
        nodes[i].pressure = nodes[nb].pressure;
    }
  }
  std::sort(nodes.begin(), nodes.end(), [](const ContactNodeResult& a, const ContactNodeResult& b) {
    return a.position.x() != b.position.x() ? a.position.x() < b.position.x()
                                            : a.position.y() < b.position.y();
  });
  return nodes;
}

double largest_tension(const ConstraintSet& set, const Eigen::VectorXd& lambda) {
  double tension = 0.0;
  for (int j = 0; j < set.n_rows(); ++j) {
    if (set.rows[j].weight_w > 0.0)
      tension = std::max(tension, -lambda[j] / set.rows[j].weight_w);
  }
  return tension;
}

namespace {

/// The Coulomb state of every contact node: its row's (nodal rows); for Gauss rows Stick if a
/// closed row sharing the node sticks, else Slip if one slips, else Open.
std::vector<FrictionState> node_friction_states(const ConstraintSet& set,
                                                const std::vector<FrictionState>& row_state) {
  std::vector<FrictionState> state(set.nodes.size(), FrictionState::Open);
  for (int j = 0; j < set.n_rows(); ++j) {
    const ContactConstraint& row = set.rows[j];
    for (int s = 0; s < row.n_shares; ++s) {
      if (row.shares[s] == 0.0)
        continue;
      FrictionState& n = state[row.share_nodes[s]];
      if (row_state[j] == FrictionState::Stick ||
          (row_state[j] == FrictionState::Slip && n == FrictionState::Open)) {
        n = row_state[j];
      }
    }
  }
  return state;
}

}  // namespace

void add_friction_results(const ConstraintSet& set, const RowState& rows,
                          const FrictionRowState& friction, std::vector<ContactNodeResult>& nodes) {
  // The shear is to lambda_T what the pressure is to lambda: the same conversion, node order
  // and degenerate-node rule.
  const RowState tangential{friction.slip, friction.force_t, rows.active, rows.candidate_of_row};
  std::vector<double> shear(set.nodes.size(), 0.0);
  for (const ContactNodeResult& t : node_results(set, tangential, friction.node_slip))
    shear[find_contact_node(set.nodes, t.node)] = t.pressure;
  const std::vector<FrictionState> state = node_friction_states(set, friction.state);
  for (ContactNodeResult& r : nodes) {
    const int i = find_contact_node(set.nodes, r.node);
    r.shear = shear[i];
    r.slip = friction.node_slip[i];
    r.slip_increment = friction.node_slip[i] - friction.node_slip_prev[i];
    r.friction = state[i];
  }
}

}  // namespace cs::solver

#pragma once
// Per-node results of a contact solve, from the state of every constraint row: the normal
// pressure and gap (any analysis) and the shear, slip and Coulomb state (friction). Used by
// solver/contact/contact_analysis.cpp (the review of rows outside the candidates is the
// search's: solver/contact/contact_search.hpp).

#include <vector>

#include <Eigen/Core>

#include "solver/contact/constraint_set.hpp"
#include "solver/contact/contact_result.hpp"

namespace cs::solver {

/// A candidate whose |gap| is below this (relative to the element depth) touches the target.
inline constexpr double kTouchingGap = 1e-10;

/// The state of every row of a constraint set after a solve.
struct RowState {
  const Eigen::VectorXd& gap;                ///< g = g0 + B u
  const Eigen::VectorXd& lambda;             ///< force (0 outside the candidates)
  const std::vector<char>& active;           ///< the algorithm's last active flags
  const std::vector<int>& candidate_of_row;  ///< -1 outside the candidates (the search)
};

/// The tangential state of every row of a constraint set after a frictional solve.
struct FrictionRowState {
  const Eigen::VectorXd& slip;              ///< s = s0 + T u
  const Eigen::VectorXd& force_t;           ///< lambda_T (0 outside the candidates)
  const std::vector<FrictionState>& state;  ///< Open outside the candidates
  const Eigen::VectorXd& node_slip;         ///< s per contact node (set.nodes order)
  const Eigen::VectorXd& node_slip_prev;    ///< the previous step's, same order
};

/// Per-node results, sorted by position. The pressure of a node is its multiplier coefficient
/// p_a = lambda_a / w_a (weighted rows: mortar, ss with LM/MPC; the value of p_h at a corner, and
/// at a Q8 mid-side node its Bernstein coefficient, which is what the Coulomb law of a row
/// bounds) or its nodal force over its consistent weight (ns; ss Gauss rows, whose forces are
/// shared out with N_a); a node whose consistent weight vanishes reports its neighbour's. The
/// force of a weighted row's node is lambda_a = int p_h Phi_a (r) ds.
std::vector<ContactNodeResult> node_results(const ConstraintSet& set, const RowState& rows,
                                            const Eigen::VectorXd& node_gap);

/// The largest tension over the rows of `set`: max(0, max over j of -lambda_j / w_j).
double largest_tension(const ConstraintSet& set, const Eigen::VectorXd& lambda);

/// Adds the shear (from lambda_T exactly as the pressure from lambda), the slip, its increment
/// and the Coulomb state to `nodes` (the node_results of the same set and rows).
void add_friction_results(const ConstraintSet& set, const RowState& rows,
                          const FrictionRowState& friction, std::vector<ContactNodeResult>& nodes);

}  // namespace cs::solver

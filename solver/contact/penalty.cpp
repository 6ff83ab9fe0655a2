#include "solver/contact/penalty.hpp"

#include <algorithm>

namespace cs::solver {

RowLaw PenaltyRules::law(int j, bool active) const {
  return active ? RowLaw{1.0, kp_[j], 0.0} : RowLaw{1.0, 0.0, 0.0};
}

bool PenaltyRules::next_active(int, double, double gap) const {
  return gap < 0.0;
}

double PenaltyRules::residual(int j, double lambda, double gap) const {
  return lambda - kp_[j] * std::max(0.0, -gap);
}

AlgorithmOutcome solve_penalty(const AlgorithmInput& in) {
  const PenaltyRules rules(in.penalty_kp);
  return run_active_set(in.problem, rules, in.initial_active, in.settings.max_iterations);
}

AlgorithmOutcome solve_penalty_frictional(const FrictionalInput& in) {
  const PenaltyRules normal(in.penalty_kp);
  const Eigen::VectorXd kt = in.settings.fkt * in.penalty_kp;
  const TangentialPenaltyRules tangential(kt, in.force_t_prev, in.slip_prev);
  return run_frictional_active_set(in.problem, normal, tangential, in.settings.mu,
                                   in.initial_states, in.settings.max_iterations);
}

}  // namespace cs::solver

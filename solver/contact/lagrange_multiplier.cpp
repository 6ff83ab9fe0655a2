#include "solver/contact/lagrange_multiplier.hpp"

#include <algorithm>

namespace cs::solver {

RowLaw LagrangeMultiplierRules::law(int, bool active) const {
  return active ? RowLaw{0.0, 1.0, 0.0} : RowLaw{1.0, 0.0, 0.0};
}

bool LagrangeMultiplierRules::next_active(int j, double lambda, double gap) const {
  return lambda - c_[j] * gap > 0.0;
}

double LagrangeMultiplierRules::residual(int j, double lambda, double gap) const {
  return std::min(lambda, c_[j] * gap);
}

AlgorithmOutcome solve_lagrange_multiplier(const AlgorithmInput& in) {
  const LagrangeMultiplierRules rules(in.problem.rho);
  return run_active_set(in.problem, rules, in.initial_active, in.settings.max_iterations);
}

AlgorithmOutcome solve_lagrange_multiplier_frictional(const FrictionalInput& in) {
  const int m = in.n_pairs();
  const LagrangeMultiplierRules normal(in.problem.rho);  // reads rho of rows 0..m-1
  if (in.settings.tangential == TangentialEnforcement::LagrangeMultiplier) {
    const Eigen::VectorXd c = in.problem.rho.head(m);
    const TangentialMultiplierRules tangential(c, in.slip_prev);
    return run_frictional_active_set(in.problem, normal, tangential, in.settings.mu,
                                     in.initial_states, in.settings.max_iterations);
  }
  const Eigen::VectorXd kt = in.settings.fkt * in.penalty_kp;
  const TangentialPenaltyRules tangential(kt, in.force_t_prev, in.slip_prev);
  return run_frictional_active_set(in.problem, normal, tangential, in.settings.mu,
                                   in.initial_states, in.settings.max_iterations);
}

}  // namespace cs::solver

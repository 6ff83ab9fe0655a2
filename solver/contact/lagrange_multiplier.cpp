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

}  // namespace cs::solver

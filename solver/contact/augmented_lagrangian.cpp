#include "solver/contact/augmented_lagrangian.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace cs::solver {

RowLaw AugmentedLagrangianRules::law(int j, bool active) const {
  return active ? RowLaw{1.0, kp_[j], lambda_hat_[j]} : RowLaw{1.0, 0.0, 0.0};
}

bool AugmentedLagrangianRules::next_active(int j, double, double gap) const {
  return lambda_hat_[j] - kp_[j] * gap > 0.0;
}

double AugmentedLagrangianRules::residual(int j, double lambda, double gap) const {
  return lambda - std::max(0.0, lambda_hat_[j] - kp_[j] * gap);
}

AlgorithmOutcome solve_augmented_lagrangian(const AlgorithmInput& in) {
  const int m = in.problem.size();
  Eigen::VectorXd lambda_hat = Eigen::VectorXd::Zero(m);
  std::vector<char> active = in.initial_active;
  int total_iterations = 0;
  double penetration_ratio = 0.0;
  for (int aug = 0;; ++aug) {
    const AugmentedLagrangianRules rules(in.penalty_kp, lambda_hat);
    AlgorithmOutcome out = run_active_set(in.problem, rules, active, in.settings.max_iterations);
    total_iterations += out.iterations;
    out.iterations = total_iterations;
    out.augmentations = aug;
    if (out.status != ContactStatus::Converged)
      return out;
    // Largest penetration of a closed row relative to FTOLN h.
    penetration_ratio = 0.0;
    for (int j = 0; j < m; ++j) {
      if (out.step.lambda[j] > 0.0) {
        penetration_ratio = std::max(penetration_ratio, -out.step.gap[j] / in.depth_h[j]);
      }
    }
    if (penetration_ratio <= in.settings.ftoln)
      return out;
    if (aug + 1 >= in.settings.max_augmentations) {
      out.status = ContactStatus::NotConverged;
      out.failure = ContactFailure::AugmentationLimit;
      out.reason = fmt::format(
          "augmentation cap of {} reached: largest penetration {:.3g} h > "
          "FTOLN = {}",
          in.settings.max_augmentations, penetration_ratio, in.settings.ftoln);
      return out;
    }
    lambda_hat = out.step.lambda.cwiseMax(0.0);
    active = out.active;
  }
}

}  // namespace cs::solver

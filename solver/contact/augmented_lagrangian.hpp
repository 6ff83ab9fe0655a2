#pragma once
// AL, the augmented Lagrangian method: the penalty law shifted by a multiplier estimate,
//
//   lambda = max(0, lambda_hat - k g),   k = FKN (E / h) w   (as in solver/contact/penalty.hpp),
//
// solved by the active-set loop for fixed lambda_hat; then, while some closed row penetrates by
// more than FTOLN x h (h its underlying element depth), the estimate is updated
// lambda_hat <- lambda and the loop runs again (Uzawa-type augmentation). The first pass is the
// penalty method (lambda_hat = 0): with the default FKN = 1 the penetration p h / E is far
// below FTOLN h = 0.1 h for the study's loads, so AL and PM give the same answer, as the study
// observed. The augmentation count and the total number of linear solves are reported.

#include "solver/contact/active_set_solver.hpp"

namespace cs::solver {

/// The active-set rules of one augmented Lagrangian pass with fixed multiplier estimates.
class AugmentedLagrangianRules : public ActiveSetRules {
 public:
  AugmentedLagrangianRules(const Eigen::VectorXd& kp, const Eigen::VectorXd& lambda_hat)
      : kp_(kp), lambda_hat_(lambda_hat) {}
  RowLaw law(int j, bool active) const override;
  bool next_active(int j, double lambda, double gap) const override;
  double residual(int j, double lambda, double gap) const override;

 private:
  const Eigen::VectorXd& kp_;
  const Eigen::VectorXd& lambda_hat_;
};

/// Solves the condensed problem by the augmented Lagrangian method.
AlgorithmOutcome solve_augmented_lagrangian(const AlgorithmInput& input);

}  // namespace cs::solver

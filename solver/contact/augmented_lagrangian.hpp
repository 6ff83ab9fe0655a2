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
//
// With friction (mu > 0) the tangent is the penalty of solver/contact/coulomb_friction.hpp,
// lambda_T = lambda_hat_T + kt (s - s_prev) while sticking (kt = FKT x k), and the augmentation
// acts on it too: lambda_hat_T starts at the previous step's shear (the first pass is the penalty
// method) and is set to the converged shear while some sticking row slips by more than FTOLT x h
// in the step, so that the elastic slip of a sticking point tends to zero. Each estimate is
// updated while its own tolerance fails, until both hold. (Where no augmentation is needed,
// AL and PM give the same answer; with friction the default FTOLT makes them differ.)
// Limitation: with ss Gauss-point rows (two per Q4 side, three per Q8 side) exact stick
// over-constrains the relative displacement of a segment next to a slipping row, so the stick
// slip increments stagnate (Cattaneo-Mindlin, Q4, h = a / 8: about 2e-5 h, drifting shear at
// the stick edge) and FTOLT below that ends at the augmentation cap (AugmentationLimit).

#include "solver/contact/active_set_solver.hpp"
#include "solver/contact/frictional_active_set.hpp"

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

/// Solves the frictional condensed problem by the augmented Lagrangian method (normal and
/// tangent augmented).
AlgorithmOutcome solve_augmented_lagrangian_frictional(const FrictionalInput& input);

}  // namespace cs::solver

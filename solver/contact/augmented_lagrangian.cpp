#include "solver/contact/augmented_lagrangian.hpp"

#include <algorithm>

#include <cmath>

#include <fmt/format.h>

#include "solver/contact/penalty.hpp"

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
  // The first pass is the penalty method's solve (no multiplier estimate yet): an AL solve that
  // stops there is PM's, step for step (solver/contact/repeated_solve.hpp).
  AlgorithmOutcome out = solve_penalty(in);
  int total_iterations = out.iterations;
  for (int aug = 0;; ++aug) {
    out.iterations = total_iterations;
    out.augmentations = aug;
    if (out.status != ContactStatus::Converged)
      return out;
    // Largest penetration of a closed row relative to FTOLN h.
    double penetration_ratio = 0.0;
    for (int j = 0; j < in.problem.size(); ++j) {
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
    const Eigen::VectorXd lambda_hat = out.step.lambda.cwiseMax(0.0);
    const AugmentedLagrangianRules rules(in.penalty_kp, lambda_hat);
    out = run_active_set(in.problem, rules, out.active, in.settings.max_iterations);
    total_iterations += out.iterations;
  }
}

namespace {

/// How far an AL pass is from its tolerances: the largest penetration of a closed row over
/// FTOLN h and the largest slip increment of a sticking row over FTOLT h (> 1: augment).
double frictional_violation(const FrictionalInput& in, const AlgorithmOutcome& out,
                            double& penetration_ratio, double& slip_ratio) {
  const int m = in.n_pairs();
  penetration_ratio = 0.0;
  slip_ratio = 0.0;
  for (int j = 0; j < m; ++j) {
    if (out.step.lambda[j] > 0.0)
      penetration_ratio = std::max(penetration_ratio, -out.step.gap[j] / in.depth_h[j]);
    if (out.friction[j] == FrictionState::Stick) {
      const double slip_increment = -out.step.gap[m + j] - in.slip_prev[j];
      slip_ratio = std::max(slip_ratio, std::abs(slip_increment) / in.depth_h[j]);
    }
  }
  return std::max(penetration_ratio / in.settings.ftoln, slip_ratio / in.settings.ftolt);
}

}  // namespace

AlgorithmOutcome solve_augmented_lagrangian_frictional(const FrictionalInput& in) {
  const int m = in.n_pairs();
  const Eigen::VectorXd kt = in.settings.fkt * in.penalty_kp;
  // The first pass is the penalty method's (normal estimate 0, tangential estimate the previous
  // step's shear): an AL solve that stops there is PM's, step for step.
  AlgorithmOutcome out = solve_penalty_frictional(in);
  Eigen::VectorXd lambda_hat_n = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd lambda_hat_t = in.force_t_prev;
  int total_iterations = out.iterations;
  for (int aug = 0;; ++aug) {
    out.iterations = total_iterations;
    out.augmentations = aug;
    if (out.status != ContactStatus::Converged)
      return out;
    double penetration_ratio = 0.0, slip_ratio = 0.0;
    if (frictional_violation(in, out, penetration_ratio, slip_ratio) <= 1.0)
      return out;
    if (aug + 1 >= in.settings.max_augmentations) {
      out.status = ContactStatus::NotConverged;
      out.failure = ContactFailure::AugmentationLimit;
      out.reason = fmt::format(
          "augmentation cap of {} reached: largest penetration {:.3g} h (FTOLN = {}), largest "
          "stick slip increment {:.3g} h (FTOLT = {})",
          in.settings.max_augmentations, penetration_ratio, in.settings.ftoln, slip_ratio,
          in.settings.ftolt);
      return out;
    }
    // Each estimate is augmented where its own tolerance fails (as without friction, where AL
    // is PM while the penetration is within FTOLN h).
    if (penetration_ratio > in.settings.ftoln)
      lambda_hat_n = out.step.lambda.head(m).cwiseMax(0.0);
    if (slip_ratio > in.settings.ftolt)
      lambda_hat_t = out.step.lambda.tail(m);
    const AugmentedLagrangianRules normal(in.penalty_kp, lambda_hat_n);
    const TangentialPenaltyRules tangential(kt, lambda_hat_t, in.slip_prev);
    out = run_frictional_active_set(in.problem, normal, tangential, in.settings.mu, out.active,
                                    in.settings.max_iterations);
    total_iterations += out.iterations;
  }
}

}  // namespace cs::solver

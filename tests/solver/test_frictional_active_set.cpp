// The frictional active-set loop's linear solve on small condensed problems whose answers are
// known: a slipping pair's coupled (non-symmetric) system against an independent solve, and a
// singular system, which is a status with its reason.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "solver/contact/frictional_active_set.hpp"

namespace cs::solver::test_frictional_active_set {
namespace {

/// Normal rows held closed (g = 0) in every iteration and judged complete.
class ClosedNormals : public ActiveSetRules {
 public:
  RowLaw law(int, bool active) const override { return active ? RowLaw{0.0, 1.0, 0.0} : RowLaw{}; }
  bool next_active(int, double, double) const override { return true; }
  double residual(int, double, double) const override { return 0.0; }
};

/// A tangential trial force of `trial` on every pair (stick law lambda_T = 0, not reached when
/// the trial exceeds the Coulomb bound).
class FixedTrial : public TangentialRules {
 public:
  explicit FixedTrial(double trial) : trial_(trial) {}
  RowLaw stick_law(int) const override { return RowLaw{}; }
  double trial(int, double, double) const override { return trial_; }

 private:
  double trial_;
};

// One pair, pressed in (g0 = -0.3) and slipping along +t: the normal row closes the gap,
// (W mu)_N = -g0_N, and the tangential row carries mu_c times the normal force,
// mu_T - rho_T (W mu)_T = mu_c (mu_N - rho_N (W mu)_N). W couples the two rows, so the system is
// not symmetric: solved as its transpose, or with the slip's sign or the factor mu_c wrong, mu
// differs from the solve here.
TEST(FrictionalActiveSet, ASlippingPairSolvesItsCoupledSystem) {
  Eigen::MatrixXd W(2, 2);
  W << 2.0, 0.5, 0.5, 1.0;
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(2);
  const Eigen::Vector2d rho(0.1, 0.3);
  const Eigen::Vector2d g0(-0.3, 0.0);
  const double mu_c = 0.4;
  const CondensedProblem problem{W, d, rho, g0};
  const AlgorithmOutcome out = run_frictional_active_set(problem, ClosedNormals{}, FixedTrial{1e6},
                                                         mu_c, {1, kSlipPositiveCode}, 5);
  ASSERT_EQ(out.status, ContactStatus::Converged) << out.reason;
  EXPECT_EQ(out.iterations, 1);
  // The same two laws, assembled row by row here.
  Eigen::Matrix2d M;
  M.row(0) = W.row(0);
  M.row(1) = Eigen::RowVector2d(0.0, 1.0) - rho[1] * W.row(1) -
             mu_c * (Eigen::RowVector2d(1.0, 0.0) - rho[0] * W.row(0));
  const Eigen::Vector2d expected = M.fullPivLu().solve(Eigen::Vector2d(-g0[0], 0.0));
  EXPECT_LT((out.step.mu - expected).norm(), 1e-13) << out.step.mu.transpose();
  EXPECT_NEAR(out.step.gap[0], 0.0, 1e-15);
  EXPECT_GT(out.step.lambda[0], 0.0);  // pressed: a compressive normal force
  EXPECT_DOUBLE_EQ(out.step.lambda[1], mu_c * out.step.lambda[0]);
}

// Two closed normal rows of one compliance (W's normal block of rank one): the system is exactly
// singular, and the loop stops not converged with the reason, not with a NaN.
TEST(FrictionalActiveSet, ASingularSystemIsAStatusWithItsReason) {
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(4, 4);
  W.topLeftCorner(2, 2).setOnes();
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(4);
  const Eigen::VectorXd rho = Eigen::VectorXd::Constant(4, 0.1);
  const Eigen::VectorXd g0 = Eigen::VectorXd::Constant(4, -0.1);
  const CondensedProblem problem{W, d, rho, g0};
  const AlgorithmOutcome out = run_frictional_active_set(problem, ClosedNormals{}, FixedTrial{0.0},
                                                         0.3, {1, 1, kStickCode, kStickCode}, 5);
  EXPECT_EQ(out.status, ContactStatus::NotConverged);
  EXPECT_EQ(out.failure, ContactFailure::SingularSystem);
  EXPECT_NE(out.reason.find("frictional active-set iteration 1: the condensed frictional contact "
                            "system of 4 equations is singular (reciprocal condition 0)"),
            std::string::npos)
      << out.reason;
  EXPECT_FALSE(out.has_solution());
}

}  // namespace
}  // namespace cs::solver::test_frictional_active_set

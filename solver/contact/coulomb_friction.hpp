#pragma once
// Coulomb friction, the tangential half of a frictional contact method: how a sticking contact
// point holds (its stick law) and when it slips (its trial force), per pair of rows (the normal
// row j and its tangential twin, solver/contact/constraint_set.hpp). With lambda_N >= 0 the
// normal force, lambda_T the shear force transmitted along t and s the slip of the row,
//
//   |lambda_T| <= mu lambda_N;   stick: slip increment s - s_prev = 0 (or elastic, below);
//   slip: lambda_T = mu lambda_N sign(s - s_prev),
//
// s_prev the slip at the end of the previous load step (friction is path dependent). A row is
// given the stick law while |trial| <= mu lambda_N and the slip law sigma = sign(trial) beyond:
//   - TangentialPenaltyRules (PM, AL, LMP): the return mapping of an elastic-slip law,
//       stick: lambda_T = lambda_hat + kt (s - s_prev),   trial = lambda_hat + kt (s - s_prev),
//     kt = FKT x FKN x (E / h) w, lambda_hat = the previous step's lambda_T (AL: the augmented
//     estimate); a sticking point slips elastically by (lambda_T - lambda_hat) / kt.
//   - TangentialMultiplierRules (PLM): exact stick by a tangential multiplier,
//       stick: s = s_prev,   trial = lambda_T + c (s - s_prev),   c = (E / h) w,
//     the semi-smooth Newton (primal-dual active set) form of the Coulomb law (Hueber, Stadler
//     & Wohlmuth, SIAM J. Sci. Comput. 30, 2008).

#include <Eigen/Core>

#include "solver/contact/active_set_solver.hpp"

namespace cs::solver {

/// The stick law and the trial force of one tangential enforcement.
class TangentialRules {
 public:
  virtual ~TangentialRules() = default;
  /// The stick law of pair j on (lambda_T, s): alpha lambda_T + beta s = gamma.
  virtual RowLaw stick_law(int j) const = 0;
  /// The trial force of pair j: the row sticks while |trial| <= mu lambda_N, else slips along
  /// sign(trial).
  virtual double trial(int j, double lambda_t, double s) const = 0;
};

/// The penalty tangent with its return mapping (PM, AL, LMP).
class TangentialPenaltyRules : public TangentialRules {
 public:
  /// kt, lambda_hat, s_prev: per pair; the references must outlive the rules.
  TangentialPenaltyRules(const Eigen::VectorXd& kt, const Eigen::VectorXd& lambda_hat,
                         const Eigen::VectorXd& s_prev)
      : kt_(kt), lambda_hat_(lambda_hat), s_prev_(s_prev) {}
  RowLaw stick_law(int j) const override;
  double trial(int j, double lambda_t, double s) const override;

 private:
  const Eigen::VectorXd& kt_;
  const Eigen::VectorXd& lambda_hat_;
  const Eigen::VectorXd& s_prev_;
};

/// Exact stick by tangential Lagrange multipliers (PLM).
class TangentialMultiplierRules : public TangentialRules {
 public:
  /// c (the rows' stiffness scale) and s_prev per pair; the references must outlive the rules.
  TangentialMultiplierRules(const Eigen::VectorXd& c, const Eigen::VectorXd& s_prev)
      : c_(c), s_prev_(s_prev) {}
  RowLaw stick_law(int j) const override;
  double trial(int j, double lambda_t, double s) const override;

 private:
  const Eigen::VectorXd& c_;
  const Eigen::VectorXd& s_prev_;
};

/// The Coulomb bound mu max(0, lambda_N).
inline double coulomb_bound(double mu, double lambda_n) {
  return lambda_n > 0.0 ? mu * lambda_n : 0.0;
}

/// The complementarity residual of the Coulomb law: lambda_T - clamp(trial, -bound, bound).
double coulomb_residual(double lambda_t, double trial, double bound);

}  // namespace cs::solver

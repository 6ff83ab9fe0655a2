#pragma once
// LM, Lagrange multipliers on the normal (the study's LMP and PLM, which coincide without
// friction): exact zero penetration on the active rows, zero force on the others, i.e. the
// saddle-point problem of the constrained minimum of the elastic energy, on the condensed
// problem. Primal-dual active set (semi-smooth Newton for min(lambda, c g) = 0):
//
//   active next  <=>  lambda - c g > 0,   c = (E / h) w  (the row's stiffness scale),
//
// starting from every candidate active. At convergence lambda >= 0, g >= 0 and lambda g = 0
// hold on every row to the tolerance.

#include "solver/contact/active_set_solver.hpp"

namespace cs::solver {

/// The active-set rules of the Lagrange multiplier method.
class LagrangeMultiplierRules : public ActiveSetRules {
 public:
  explicit LagrangeMultiplierRules(const Eigen::VectorXd& c) : c_(c) {}
  RowLaw law(int j, bool active) const override;
  bool next_active(int j, double lambda, double gap) const override;
  double residual(int j, double lambda, double gap) const override;

 private:
  const Eigen::VectorXd& c_;
};

/// Solves the condensed problem by Lagrange multipliers.
AlgorithmOutcome solve_lagrange_multiplier(const AlgorithmInput& input);

}  // namespace cs::solver

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
//
// With friction (mu > 0) the tangent is enforced as settings.tangential says (see
// solver/contact/coulomb_friction.hpp): TangentialEnforcement::Penalty is the study's LMP
// (penalty tangent kt = FKT x FKN x (E / h) w with its return mapping), LagrangeMultiplier its
// PLM (exact stick: zero slip increment at every sticking row). Normal and tangential states are
// updated together in one semi-smooth Newton loop (solver/contact/frictional_active_set.hpp).

#include "solver/contact/active_set_solver.hpp"
#include "solver/contact/frictional_active_set.hpp"

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

/// Solves the frictional condensed problem by normal Lagrange multipliers and the tangential
/// enforcement of input.settings (LMP or PLM).
AlgorithmOutcome solve_lagrange_multiplier_frictional(const FrictionalInput& input);

}  // namespace cs::solver

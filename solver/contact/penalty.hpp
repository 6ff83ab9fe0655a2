#pragma once
// PM, the penalty method: a row's contact force is lambda = k (-g) while it penetrates
// (g < 0) and 0 otherwise, with the penalty stiffness
//
//   k = FKN x (E / h) x w      (force / length, per unit thickness | per radian),
//
// E the host element's Young's modulus, h the underlying element depth and w the row's
// tributary weight (solver/contact/constraint_set.hpp): a penetration d gives the pressure
// FKN E d / h, i.e. the penalty is FKN times the stiffness of the underlying element layer.
// The active set is updated by the sign of the gap (semi-smooth Newton on the piecewise linear
// law); it starts from every candidate active.
//
// With friction (mu > 0) the tangent is a penalty too, kt = FKT x k, with the return mapping of
// solver/contact/coulomb_friction.hpp: lambda_T = lambda_T,prev + kt (s - s_prev) capped at
// mu lambda_N; a sticking point slips elastically by the shear increment over kt.

#include "solver/contact/active_set_solver.hpp"
#include "solver/contact/frictional_active_set.hpp"

namespace cs::solver {

/// The active-set rules of the penalty method.
class PenaltyRules : public ActiveSetRules {
 public:
  explicit PenaltyRules(const Eigen::VectorXd& kp) : kp_(kp) {}
  RowLaw law(int j, bool active) const override;
  bool next_active(int j, double lambda, double gap) const override;
  double residual(int j, double lambda, double gap) const override;

 private:
  const Eigen::VectorXd& kp_;
};

/// Solves the condensed problem by the penalty method.
AlgorithmOutcome solve_penalty(const AlgorithmInput& input);

/// Solves the frictional condensed problem by the penalty method (penalty normal and tangent).
AlgorithmOutcome solve_penalty_frictional(const FrictionalInput& input);

}  // namespace cs::solver

#pragma once
// The active-set (semi-smooth Newton) loop of Coulomb friction, on the condensed problem of
// solver/contact/condensation.hpp with 2m rows: the m candidate normal rows g = g0 + B u, then
// their tangential twins written as r = -s = -(s0 + T u), so that the force on the DOFs is
// B^T lambda_N - T^T lambda_T and every row reads like a normal one:
//
//   r = r0 + d + W mu,   lambda = mu - rho (r - r0)   (2m rows; rho repeated for the twins).
//
// Pair j is row j (normal) and row m + j (tangential). In one iteration every row obeys a linear
// law alpha lambda_j + beta r_j + kappa lambda_{partner} = gamma:
//   - the normal row: the algorithm's ActiveSetRules (kappa = 0);
//   - the tangential row: open (normal inactive, or an empty twin: a node whose slip is held by
//     supports, which take the shear) lambda_T = 0; stick: the TangentialRules'
//     stick law (solver/contact/coulomb_friction.hpp); slip with sign sigma: lambda_T =
//     sigma mu lambda_N, the one coupled law (kappa = -sigma mu).
// Substituted, the laws give a dense nonsymmetric system in mu (rows equilibrated, LU with
// partial pivoting). Next states: the normal row by the ActiveSetRules; the tangential row
// sticks while |trial| <= mu max(0, lambda_N), else slips along sign(trial). Residual: the
// normal rules' and the Coulomb residual lambda_T - clamp(trial, -mu lambda_N, mu lambda_N).
//
// Like run_active_set, the loop always terminates: converged when the relative residual is below
// kActiveSetTolerance or the states reproduce themselves, not converged at the iteration cap, on
// cycling (a state vector repeats), a singular system or a non-finite solution.

#include <vector>

#include <Eigen/Core>

#include "solver/contact/active_set_solver.hpp"
#include "solver/contact/coulomb_friction.hpp"

namespace cs::solver {

/// The tangential state codes of a frictional loop (entries m..2m-1 of its state vector).
inline constexpr char kStickCode = 0;
inline constexpr char kSlipPositiveCode = 1;  ///< slipping along +t
inline constexpr char kSlipNegativeCode = 2;  ///< slipping along -t

/// What every frictional algorithm reads.
struct FrictionalInput {
  const CondensedProblem& problem;      ///< 2m rows: normals, then tangential twins (r = -s)
  const Eigen::VectorXd& penalty_kp;    ///< m: FKN (E / h) w per pair (PM, AL; FKT scales it)
  const Eigen::VectorXd& depth_h;       ///< m: underlying element depth (FTOLN, FTOLT)
  const ContactSettings& settings;      ///< mu, FKT, FTOLT, tangential enforcement, caps
  const Eigen::VectorXd& slip_prev;     ///< m: s at the end of the previous step
  const Eigen::VectorXd& force_t_prev;  ///< m: lambda_T at the end of the previous step
  /// The first states (2m): normal active flags, then tangential codes.
  std::vector<char> initial_states;
  int n_pairs() const { return problem.size() / 2; }
};

/// Runs the frictional loop from `states` (2m: normal active flags, then tangential codes) with
/// at most `max_iterations` solves. The outcome's `active` holds the last 2m states, its
/// `friction` the state of every pair, its step the 2m forces and rows (r = -s on the twins).
AlgorithmOutcome run_frictional_active_set(const CondensedProblem& problem,
                                           const ActiveSetRules& normal,
                                           const TangentialRules& tangential, double mu,
                                           std::vector<char> states, int max_iterations);

/// The Coulomb state of pair j from a frictional loop's 2m states.
FrictionState friction_state(const std::vector<char>& states, int j);

}  // namespace cs::solver

#pragma once
// The active-set (semi-smooth Newton / primal-dual active set) loop shared by the contact
// algorithms, on the condensed problem of solver/contact/condensation.hpp:
//
//   g = g0 + d + W mu,   lambda = mu - rho (g - g0),
//
// m rows, g the gaps, lambda the contact forces (>= 0 compressive). In one iteration every row
// obeys a linear law alpha lambda + beta g = gamma chosen by the algorithm from the row's
// active flag (e.g. Lagrange multiplier: g = 0 if active, lambda = 0 if not). Substituting,
//   alpha mu + delta (d + W mu) = gamma - beta g0,   delta = beta - alpha rho,
// which is explicit in mu_j where delta_j = 0 and otherwise, divided by delta_j, the symmetric
// (possibly indefinite) system (W + diag(alpha / delta)) mu = ...; it is solved after the
// symmetric scaling rho^{1/2} (dense::SymmetricFactorization) by Cholesky where it is positive
// definite, and where rows are open (their term -1 against rho^{1/2} W rho^{1/2} < I makes it
// indefinite) by two Cholesky factorizations of its quasi-definite blocks; else by a
// Bunch-Kaufman LDL^T.
//
// The loop always terminates: it stops converged when the residual of the algorithm's
// complementarity function is below the tolerance or the active set reproduces itself, and
// not converged at the iteration cap, when an active set repeats an earlier one (cycling), when
// the linear system is singular, or when the solution is not finite.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/contact/contact_result.hpp"

namespace cs::solver {

/// The condensed contact problem (views; see condensation.hpp).
struct CondensedProblem {
  const Eigen::MatrixXd& W;    ///< m x m
  const Eigen::VectorXd& d;    ///< m
  const Eigen::VectorXd& rho;  ///< m, > 0
  const Eigen::VectorXd& g0;   ///< m, reference gaps (prescribed displacements included)
  /// The residual is relative to max(force_scale, max_j |lambda_j|): a floor for problems
  /// without contact forces (e.g. 1e-12 max_j rho_j h_j); > 0.
  double force_scale = 1.0;
  int size() const { return static_cast<int>(d.size()); }
};

/// The linear law alpha lambda + beta g = gamma of one row in one iteration.
struct RowLaw {
  double alpha = 1.0;
  double beta = 0.0;
  double gamma = 0.0;
};

/// One linear solve of the condensed problem.
struct ActiveSetStep {
  bool ok = false;
  ContactFailure failure_kind = ContactFailure::None;  ///< SingularSystem or NonFinite
  std::string failure;                                 ///< why not ok, one line
  Eigen::VectorXd mu;      ///< condensed unknowns (for the displacement recovery)
  Eigen::VectorXd lambda;  ///< contact forces
  Eigen::VectorXd gap;     ///< gaps
};

/// Solves the condensed problem with one law per row.
ActiveSetStep solve_with_laws(const CondensedProblem& problem, const std::vector<RowLaw>& laws);

/// What an algorithm contributes to the loop.
class ActiveSetRules {
 public:
  virtual ~ActiveSetRules() = default;
  /// The law of row j given whether it is active.
  virtual RowLaw law(int j, bool active) const = 0;
  /// Whether row j is active in the next iteration, from this iteration's force and gap.
  virtual bool next_active(int j, double lambda, double gap) const = 0;
  /// The row's complementarity residual in force units (0 at the exact solution).
  virtual double residual(int j, double lambda, double gap) const = 0;
};

/// How an active-set loop (or a whole algorithm) ended.
struct AlgorithmOutcome {
  ContactStatus status = ContactStatus::NotConverged;
  ContactFailure failure = ContactFailure::None;
  std::string reason;        ///< empty when converged
  double residual = 0.0;     ///< last max_j |residual_j| / max(force_scale, max_j |lambda_j|)
  int iterations = 0;        ///< linear solves (active-set iterations), all augmentations
  int augmentations = 0;     ///< AL multiplier updates
  std::vector<char> active;  ///< last active set (frictional loops: the 2m states)
  std::vector<FrictionState> friction;  ///< frictional loops: the state of every pair
  ActiveSetStep step;                   ///< last solution (finite, or empty on failure)
  bool has_solution() const { return step.ok; }
};

/// Relative residual below which the loop stops converged.
inline constexpr double kActiveSetTolerance = 1e-9;

/// Below this reciprocal condition number a condensed system (frictionless or coupled) counts as
/// singular, and the loop stops not converged.
inline constexpr double kMinRcond = 1e-14;

/// What every algorithm reads: the condensed problem and the per-row scales.
struct AlgorithmInput {
  const CondensedProblem& problem;
  const Eigen::VectorXd& penalty_kp;  ///< FKN (E / h) w per row (PM, AL)
  const Eigen::VectorXd& depth_h;     ///< underlying element depth per row (AL's FTOLN)
  const ContactSettings& settings;
  std::vector<char> initial_active;  ///< the first active set (PM, AL, LM)
};

/// Runs the active-set loop from `initial_active` with at most `max_iterations` solves.
AlgorithmOutcome run_active_set(const CondensedProblem& problem, const ActiveSetRules& rules,
                                std::vector<char> initial_active, int max_iterations);

}  // namespace cs::solver

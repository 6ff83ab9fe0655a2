#include "solver/contact/frictional_active_set.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "solver/contact/dense_kernels.hpp"

namespace cs::solver {

namespace {

/// The laws of one iteration: one per row, and the coefficient of the partner row's force
/// (non-zero only on slipping tangential rows).
struct CoupledLaws {
  std::vector<RowLaw> laws;
  std::vector<double> kappa;
};

ActiveSetStep failed_step(ContactFailure kind, std::string why) {
  ActiveSetStep step;
  step.failure_kind = kind;
  step.failure = std::move(why);
  return step;
}

/// Row j of the system in mu: alpha mu_j + kappa mu_q + delta_j (W mu)_j
/// - kappa rho_q (W mu)_q = gamma - beta r0_j - delta_j d_j + kappa rho_q d_q, delta = beta -
/// alpha rho, q the partner row; equilibrated by its largest coefficient. Stored as column j of
/// At = A^T (contiguous, W being symmetric).
bool fill_row(const CondensedProblem& p, const CoupledLaws& c, int j, int q, Eigen::MatrixXd& At,
              Eigen::VectorXd& rhs) {
  const RowLaw& l = c.laws[j];
  const double kappa = c.kappa[j];
  const double delta = l.beta - l.alpha * p.rho[j];
  At.col(j) = delta * p.W.col(j);
  rhs[j] = l.gamma - l.beta * p.g0[j] - delta * p.d[j];
  if (kappa != 0.0) {
    At.col(j) -= (kappa * p.rho[q]) * p.W.col(q);
    At(q, j) += kappa;
    rhs[j] += kappa * p.rho[q] * p.d[q];
  }
  At(j, j) += l.alpha;
  const double scale = At.col(j).cwiseAbs().maxCoeff();
  if (!(scale > 0.0))
    return false;
  At.col(j) /= scale;
  rhs[j] /= scale;
  return true;
}

/// Solves the condensed problem with one (possibly coupled) law per row. `lu` holds the
/// transposed system matrix (n x n, one workspace for every iteration, factorized in place by
/// the system LAPACK: Eigen's own LU took 60 % of a friction case on a fine mesh).
ActiveSetStep solve_coupled(const CondensedProblem& p, const CoupledLaws& c, dense::GeneralLu& lu) {
  const int n = p.size();
  const int m = n / 2;
  Eigen::MatrixXd& At = lu.matrix(n);
  Eigen::VectorXd rhs(n);
  for (int j = 0; j < n; ++j) {
    if (!fill_row(p, c, j, j < m ? j + m : j - m, At, rhs)) {
      return failed_step(ContactFailure::SingularSystem,
                         fmt::format("row {} has the empty law 0 = {}", j, c.laws[j].gamma));
    }
  }
  const double rcond = lu.factorize() ? lu.rcond() : 0.0;
  if (!(rcond > kMinRcond)) {
    return failed_step(ContactFailure::SingularSystem,
                       fmt::format("the condensed frictional contact system of {} equations is "
                                   "singular (reciprocal condition {:.2g}): a body is held by no "
                                   "active or sticking constraint",
                                   n, rcond));
  }
  ActiveSetStep step;
  lu.solve_transposed_in_place(rhs);
  step.mu = std::move(rhs);
  const Eigen::VectorXd v = p.d + p.W * step.mu;
  step.gap = p.g0 + v;
  step.lambda = step.mu - p.rho.cwiseProduct(v);
  // Laws that fix a force hold exactly, not only to the round-off of mu - rho v.
  for (int j = 0; j < n; ++j) {
    const RowLaw& l = c.laws[j];
    if (l.beta == 0.0 && c.kappa[j] == 0.0)
      step.lambda[j] = l.gamma / l.alpha;
  }
  for (int j = m; j < n; ++j) {
    if (c.kappa[j] != 0.0)  // lambda_T + kappa lambda_N = 0
      step.lambda[j] = -c.kappa[j] * step.lambda[j - m];
  }
  if (!step.mu.allFinite() || !step.gap.allFinite() || !step.lambda.allFinite()) {
    return failed_step(ContactFailure::NonFinite,
                       "the condensed frictional contact solution is not finite");
  }
  step.ok = true;
  return step;
}

/// The laws of every row for the states (2m).
void laws_for(const CondensedProblem& p, const std::vector<char>& states,
              const ActiveSetRules& normal, const TangentialRules& tangential, double mu,
              CoupledLaws& c) {
  const int m = static_cast<int>(states.size()) / 2;
  for (int j = 0; j < m; ++j) {
    c.laws[j] = normal.law(j, states[j] != 0);
    c.kappa[j] = 0.0;
    c.kappa[m + j] = 0.0;
    if (states[j] == 0 || p.W(m + j, m + j) == 0.0) {
      // Open: no shear. A tangential twin none of whose DOFs is free (W's column is zero: a
      // node on a symmetry line against a rigid target) cannot slip; its support takes the
      // shear, and the row carries none.
      c.laws[m + j] = RowLaw{1.0, 0.0, 0.0};
    } else if (states[m + j] == kStickCode) {
      const RowLaw l = tangential.stick_law(j);  // on (lambda_T, s); the row holds r = -s
      c.laws[m + j] = RowLaw{l.alpha, -l.beta, l.gamma};
    } else {
      c.laws[m + j] = RowLaw{1.0, 0.0, 0.0};
      c.kappa[m + j] = states[m + j] == kSlipPositiveCode ? -mu : mu;
    }
  }
}

/// Open rows carry the stick code, so that equal physical states compare equal.
void canonicalize(std::vector<char>& states) {
  const int m = static_cast<int>(states.size()) / 2;
  for (int j = 0; j < m; ++j) {
    if (states[j] == 0)
      states[m + j] = kStickCode;
  }
}

/// The states of the next iteration from a solution (2m), and the largest complementarity
/// residual (force units).
double next_states(const ActiveSetStep& step, const ActiveSetRules& normal,
                   const TangentialRules& tangential, double mu, std::vector<char>& next) {
  const int m = static_cast<int>(next.size()) / 2;
  double residual = 0.0;
  for (int j = 0; j < m; ++j) {
    const double lambda_n = step.lambda[j];
    const double lambda_t = step.lambda[m + j];
    const double trial = tangential.trial(j, lambda_t, -step.gap[m + j]);
    const double bound = coulomb_bound(mu, lambda_n);
    residual = std::max({residual, std::abs(normal.residual(j, lambda_n, step.gap[j])),
                         std::abs(coulomb_residual(lambda_t, trial, bound))});
    next[j] = normal.next_active(j, lambda_n, step.gap[j]) ? 1 : 0;
    next[m + j] = std::abs(trial) <= bound ? kStickCode
                  : trial > 0.0            ? kSlipPositiveCode
                                           : kSlipNegativeCode;
  }
  canonicalize(next);
  return residual;
}

}  // namespace

FrictionState friction_state(const std::vector<char>& states, int j) {
  const int m = static_cast<int>(states.size()) / 2;
  if (states[j] == 0)
    return FrictionState::Open;
  return states[m + j] == kStickCode ? FrictionState::Stick : FrictionState::Slip;
}

AlgorithmOutcome run_frictional_active_set(const CondensedProblem& problem,
                                           const ActiveSetRules& normal,
                                           const TangentialRules& tangential, double mu,
                                           std::vector<char> states, int max_iterations) {
  const int n = problem.size();
  const int m = n / 2;
  canonicalize(states);
  AlgorithmOutcome out;
  std::map<std::vector<char>, int> visited;  // states -> iteration that used them
  CoupledLaws laws{std::vector<RowLaw>(n), std::vector<double>(n, 0.0)};
  std::vector<char> next(n);
  dense::GeneralLu workspace;
  for (int it = 1; it <= max_iterations; ++it) {
    visited.emplace(states, it);
    laws_for(problem, states, normal, tangential, mu, laws);
    ActiveSetStep step = solve_coupled(problem, laws, workspace);
    out.iterations = it;
    if (!step.ok) {
      out.status = ContactStatus::NotConverged;
      out.failure = step.failure_kind;
      out.reason = fmt::format("frictional active-set iteration {}: {}", it, step.failure);
      break;  // out.step keeps the last finite solution, if any
    }
    const double residual = next_states(step, normal, tangential, mu, next);
    out.residual = residual / std::max(problem.force_scale, step.lambda.cwiseAbs().maxCoeff());
    out.active = states;
    out.step = std::move(step);
    if (out.residual <= kActiveSetTolerance || next == states) {
      out.status = ContactStatus::Converged;
      out.failure = ContactFailure::None;
      out.reason.clear();
      break;
    }
    if (it == max_iterations) {
      out.status = ContactStatus::NotConverged;
      out.failure = ContactFailure::IterationLimit;
      out.reason =
          fmt::format("frictional active-set iteration cap of {} reached (residual {:.3g})",
                      max_iterations, out.residual);
      break;
    }
    const auto seen = visited.find(next);
    if (seen != visited.end()) {
      out.status = ContactStatus::NotConverged;
      out.failure = ContactFailure::Cycling;
      out.reason = fmt::format(
          "frictional active set cycling: iteration {} would repeat the states of iteration {} "
          "(residual {:.3g})",
          it + 1, seen->second, out.residual);
      break;
    }
    states = next;
  }
  out.friction.resize(m);
  for (int j = 0; j < m && !out.active.empty(); ++j)
    out.friction[j] = friction_state(out.active, j);
  return out;
}

}  // namespace cs::solver

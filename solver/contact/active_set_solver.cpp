#include "solver/contact/active_set_solver.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "solver/contact/dense_kernels.hpp"

namespace cs::solver {

ActiveSetStep solve_with_laws(const CondensedProblem& p, const std::vector<RowLaw>& laws) {
  const int m = p.size();
  ActiveSetStep step;
  step.mu = Eigen::VectorXd::Zero(m);
  std::vector<int> implicit;
  std::vector<double> ratio;  // alpha / delta of implicit rows
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  for (int j = 0; j < m; ++j) {
    const RowLaw& l = laws[j];
    const double delta = l.beta - l.alpha * p.rho[j];
    const double scale = std::abs(l.beta) + std::abs(l.alpha) * p.rho[j];
    if (!(scale > 0.0)) {
      step.failure_kind = ContactFailure::SingularSystem;
      step.failure = fmt::format("row {} has the empty law 0 = {}", j, l.gamma);
      return step;
    }
    if (std::abs(delta) <= 1e-13 * scale) {  // explicit: alpha mu_j = gamma - beta g0_j
      step.mu[j] = (l.gamma - l.beta * p.g0[j]) / l.alpha;
    } else {
      implicit.push_back(j);
      ratio.push_back(l.alpha / delta);
      rhs[j] = (l.gamma - l.beta * p.g0[j]) / delta - p.d[j];
    }
  }
  const int nk = static_cast<int>(implicit.size());
  if (nk > 0) {
    // (W_KK + diag(alpha/delta)) mu_K = rhs_K - W_KE mu_E, scaled symmetrically by rho^{1/2}.
    Eigen::VectorXd s(nk), b(nk);
    Eigen::MatrixXd T(nk, nk);
    const Eigen::VectorXd W_mu_explicit = p.W * step.mu;  // mu is zero on implicit rows yet
    for (int a = 0; a < nk; ++a)
      s[a] = std::sqrt(p.rho[implicit[a]]);
    for (int bcol = 0; bcol < nk; ++bcol) {
      const int jb = implicit[bcol];
      for (int a = bcol; a < nk; ++a)
        T(a, bcol) = s[a] * p.W(implicit[a], jb) * s[bcol];
      T(bcol, bcol) += p.rho[jb] * ratio[bcol];
    }
    for (int a = 0; a < nk; ++a) {
      b[a] = s[a] * (rhs[implicit[a]] - W_mu_explicit[implicit[a]]);
    }
    dense::SymmetricFactorization factorization;
    if (!factorization.factorize(T) || !(factorization.rcond() > kMinRcond)) {
      step.failure_kind = ContactFailure::SingularSystem;
      step.failure = fmt::format(
          "the condensed contact system of {} equations is singular "
          "(reciprocal condition {:.2g}): a body is held by no active "
          "constraint",
          nk, factorization.rcond());
      return step;
    }
    factorization.solve_in_place(b);
    for (int a = 0; a < nk; ++a)
      step.mu[implicit[a]] = s[a] * b[a];
  }
  const Eigen::VectorXd v = p.d + p.W * step.mu;
  step.gap = p.g0 + v;
  step.lambda = step.mu - p.rho.cwiseProduct(v);
  // A law that fixes the force (beta = 0: lambda = gamma / alpha, e.g. an open row) holds
  // exactly, not only to the round-off of mu - rho v.
  for (int j = 0; j < m; ++j) {
    if (laws[j].beta == 0.0)
      step.lambda[j] = laws[j].gamma / laws[j].alpha;
  }
  if (!step.mu.allFinite() || !step.gap.allFinite() || !step.lambda.allFinite()) {
    step.failure_kind = ContactFailure::NonFinite;
    step.failure = "the condensed contact solution is not finite";
    step.mu.resize(0);
    step.gap.resize(0);
    step.lambda.resize(0);
    return step;
  }
  step.ok = true;
  return step;
}

AlgorithmOutcome run_active_set(const CondensedProblem& problem, const ActiveSetRules& rules,
                                std::vector<char> active, int max_iterations) {
  const int m = problem.size();
  AlgorithmOutcome out;
  std::map<std::vector<char>, int> visited;  // active set -> iteration that used it
  std::vector<RowLaw> laws(m);
  for (int it = 1; it <= max_iterations; ++it) {
    visited.emplace(active, it);
    for (int j = 0; j < m; ++j)
      laws[j] = rules.law(j, active[j] != 0);
    ActiveSetStep step = solve_with_laws(problem, laws);
    out.iterations = it;
    if (!step.ok) {
      out.status = ContactStatus::NotConverged;
      out.failure = step.failure_kind;
      out.reason = fmt::format("active-set iteration {}: {}", it, step.failure);
      return out;  // out.step keeps the last finite solution, if any
    }
    double residual = 0.0;
    std::vector<char> next(m);
    for (int j = 0; j < m; ++j) {
      residual = std::max(residual, std::abs(rules.residual(j, step.lambda[j], step.gap[j])));
      next[j] = rules.next_active(j, step.lambda[j], step.gap[j]) ? 1 : 0;
    }
    out.residual = residual / std::max(problem.force_scale, step.lambda.cwiseAbs().maxCoeff());
    out.active = active;
    out.step = std::move(step);
    if (out.residual <= kActiveSetTolerance || next == active) {
      out.status = ContactStatus::Converged;
      out.failure = ContactFailure::None;
      out.reason.clear();
      return out;
    }
    if (it == max_iterations)
      break;
    const auto seen = visited.find(next);
    if (seen != visited.end()) {
      out.status = ContactStatus::NotConverged;
      out.failure = ContactFailure::Cycling;
      out.reason = fmt::format(
          "active set cycling: iteration {} would repeat the active set of "
          "iteration {} (residual {:.3g})",
          it + 1, seen->second, out.residual);
      return out;
    }
    active = std::move(next);
  }
  out.status = ContactStatus::NotConverged;
  out.failure = ContactFailure::IterationLimit;
  out.reason = fmt::format("active-set iteration cap of {} reached (residual {:.3g})",
                           max_iterations, out.residual);
  return out;
}

}  // namespace cs::solver

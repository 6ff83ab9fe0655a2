#include "solver/contact/multipoint_constraint.hpp"

#include <fmt/format.h>

namespace cs::solver {

AlgorithmOutcome solve_multipoint_constraint(const AlgorithmInput& in) {
  const int m = in.problem.size();
  const std::vector<RowLaw> tied(m, RowLaw{0.0, 1.0, 0.0});
  AlgorithmOutcome out;
  out.iterations = 1;
  out.active.assign(m, 1);
  ActiveSetStep step = solve_with_laws(in.problem, tied);
  if (!step.ok) {
    out.status = ContactStatus::NotConverged;
    out.failure = step.failure_kind;
    out.reason = fmt::format("MPC: {}", step.failure);
    return out;
  }
  out.step = std::move(step);
  out.status = ContactStatus::Converged;
  return out;
}

}  // namespace cs::solver

#pragma once
// The outcome of a factorization or solve: a status with a reason, never a NaN.

#include <string>

namespace cs::solver {

/// How a linear solve ended. Input errors are not statuses: they throw ModelError.
enum class SolveStatus {
  Ok,                   ///< solved
  NotSolved,            ///< nothing computed yet
  Singular,             ///< the system has a zero-energy mode (e.g. an unconstrained body)
  NotPositiveDefinite,  ///< the factorization met a non-positive pivot (indefinite matrix)
  SolverFailure,        ///< the linear solver failed otherwise (out of memory, ...)
};

/// "ok", "not solved", "singular", "not positive definite", "solver failure".
constexpr const char* to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::Ok:
      return "ok";
    case SolveStatus::NotSolved:
      return "not solved";
    case SolveStatus::Singular:
      return "singular";
    case SolveStatus::NotPositiveDefinite:
      return "not positive definite";
    case SolveStatus::SolverFailure:
      return "solver failure";
  }
  return "unknown";
}

/// A status and, unless Ok, a one-line reason naming the cause (e.g. the unconstrained body).
struct SolveOutcome {
  SolveStatus status = SolveStatus::NotSolved;
  std::string reason;
  int failed_equation = -1;  ///< reduced-system equation of a failed pivot, if one is known
  bool ok() const { return status == SolveStatus::Ok; }
};

}  // namespace cs::solver

#pragma once
// Load steps of an incremental contact analysis (ContactAnalysis::solve_steps): friction is path
// dependent, so a frictional problem is loaded in steps (e.g. the normal load, then the
// tangential load in increments), each solved from the converged state of the step before.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "solver/model.hpp"

namespace cs::solver {

/// One load step.
struct LoadStep {
  std::string label;  ///< e.g. "normal", "tangential 2/4" (for messages)
  /// Sets the model's loads and prescribed displacement values (model.loads, the values of
  /// model.prescribed; the model the LinearStaticAnalysis reads) to their values at the end of
  /// the step (totals, not increments). May be empty (the model as it is). The analysis then
  /// re-reads the prescribed values and the loads (one forward solve).
  std::function<void()> apply;
};

/// sum_k factor_k x load case_k as one load case (every traction, pressure, point and body force
/// of each case scaled by its factor): e.g. the normal load plus a fraction of the tangential
/// load. The callables of the cases are copied.
LoadCase superpose(const std::vector<std::pair<double, LoadCase>>& terms);

}  // namespace cs::solver

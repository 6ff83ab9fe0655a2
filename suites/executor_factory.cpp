#include "suites/executor_factory.hpp"

#include <algorithm>

#include "adapters/calculix/runner.hpp"
#include "suites/calculix_executor.hpp"
#include "suites/problem_executor.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {

std::unique_ptr<GroupExecutor> make_executor_for(const CaseSpec& representative,
                                                 const ExecutorOptions& options) {
  switch (representative.solver) {
    case SolverKind::builtin:
      return std::make_unique<ProblemExecutor>(representative);
    case SolverKind::calculix:
      return std::make_unique<CalculixExecutor>(representative, options);
    case SolverKind::imported:
      throw SuiteInputError("case " + case_id(representative) +
                            ": imported results are graded from their file, not run");
  }
  throw SuiteInputError("unknown solver");
}

void require_solvers(const std::vector<CaseSpec>& cases, const ExecutorOptions& options) {
  const bool any_calculix = std::any_of(cases.begin(), cases.end(), [](const CaseSpec& s) {
    return s.solver == SolverKind::calculix;
  });
  if (any_calculix)
    adapters::calculix::require_ccx(options.ccx_executable);
}

ExecutorFactory executor_factory(const ExecutorOptions& options) {
  return [options](const CaseSpec& representative) {
    return make_executor_for(representative, options);
  };
}

}  // namespace cs::suites

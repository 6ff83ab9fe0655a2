#include "suites/executor_factory.hpp"

#include <algorithm>

#include <set>

#include "adapters/calculix/runner.hpp"
#include "adapters/protocol/solver_registry.hpp"
#include "suites/calculix_executor.hpp"
#include "suites/external_executor.hpp"
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
    case SolverKind::external: {
      ExternalRunOptions external{adapters::protocol::find_solver(
                                      representative.solver_name,
                                      adapters::protocol::solver_directories(options.solver_dirs)),
                                  options.external_time_limit_seconds, options.external_work_root};
      return std::make_unique<ExternalExecutor>(representative, std::move(external));
    }
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
  std::set<std::string> external;
  for (const auto& s : cases)
    if (s.solver == SolverKind::external)
      external.insert(s.solver_name);
  const auto dirs = adapters::protocol::solver_directories(options.solver_dirs);
  for (const auto& name : external)
    adapters::protocol::find_solver(name, dirs);
}

ExecutorFactory executor_factory(const ExecutorOptions& options) {
  return [options](const CaseSpec& representative) {
    return make_executor_for(representative, options);
  };
}

}  // namespace cs::suites

#include "suites/executor_factory.hpp"

#include <set>

#include "adapters/calculix/calculix_manifest.hpp"
#include "adapters/calculix/runner.hpp"
#include "adapters/protocol/solver_registry.hpp"
#include "adapters/registered_codes.hpp"
#include "suites/calculix_executor.hpp"
#include "suites/external_executor.hpp"
#include "suites/problem_executor.hpp"
#include "suites/run_directory.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

/// CalculiX's run options: its manifest's program and time limit unless `options` sets one.
CalculixRunOptions calculix_run_options(const ExecutorOptions& options) {
  const auto& manifest = adapters::calculix::calculix_manifest();
  return {options.external_time_limit_seconds > 0.0 ? options.external_time_limit_seconds
                                                    : manifest.time_limit_seconds,
          manifest.command.front(), options.external_work_root};
}

}  // namespace

std::unique_ptr<GroupExecutor> make_executor_for(const CaseSpec& representative,
                                                 const ExecutorOptions& options) {
  switch (representative.solver) {
    case SolverKind::builtin:
      return std::make_unique<ProblemExecutor>(representative);
    case SolverKind::external: {
      if (representative.solver_name == adapters::calculix::kCalculixName)
        return std::make_unique<CalculixExecutor>(representative, calculix_run_options(options));
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
  std::set<std::string> codes;
  for (const auto& s : cases)
    if (s.solver == SolverKind::external)
      codes.insert(s.solver_name);
  const auto dirs = adapters::protocol::solver_directories(options.solver_dirs);
  for (const auto& name : codes) {
    const auto code = adapters::find_code(name, dirs);
    if (name == adapters::calculix::kCalculixName)
      adapters::calculix::require_ccx(code.command.front());
  }
  if (!codes.empty() && options.external_work_root.empty())
    require_temporary_directory();  // where their cases' directories go
}

ExecutorFactory executor_factory(const ExecutorOptions& options) {
  return [options](const CaseSpec& representative) {
    return make_executor_for(representative, options);
  };
}

}  // namespace cs::suites

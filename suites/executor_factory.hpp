#pragma once
// The solver boundary of the engine: a case is built once (build_problem) and solved by the
// solver its spec names. make_executor_for() is the one place that dispatches on
// CaseSpec::solver; the runner takes it as its ExecutorFactory (executor_factory(options)).
//
//   builtin   -> ProblemExecutor (suites/problem_executor.hpp), the built-in solver;
//   external  -> the registered code the case's solver_name names (adapters/registered_codes.hpp):
//                CalculiX -> CalculixExecutor (suites/calculix_executor.hpp), its C++ adapter;
//                any other -> ExternalExecutor (suites/external_executor.hpp), its manifest's
//                command through the solver protocol;
//   imported  -> SuiteInputError: imported results are graded from a file, not run.
//
// Grading, rows, the gate and the report read the CaseResult and never learn which ran.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "suites/runner.hpp"

namespace cs::suites {

/// What an executor needs beyond the case (the registered codes' settings).
struct ExecutorOptions {
  /// Folders searched for external codes' manifests after the project's adapters/ and
  /// CONTACT_SUITE_SOLVER_DIRS (adapters/protocol/solver_registry.hpp).
  std::vector<std::filesystem::path> solver_dirs;
  /// Wall-clock limit of one registered code's run in seconds; 0: its manifest's.
  double external_time_limit_seconds = 0.0;
  /// Where registered codes' cases get their run directories; empty: a temporary directory.
  std::filesystem::path external_work_root;
};

/// The executor of the group `representative` belongs to, for the solver it names. Throws
/// SuiteInputError for imported results, and whatever building the problem throws.
std::unique_ptr<GroupExecutor> make_executor_for(const CaseSpec& representative,
                                                 const ExecutorOptions& options = {});

/// Checks, before any case runs, that every registered code `cases` name is available: throws
/// adapters::protocol::ManifestError for an unknown code, adapters::calculix::CalculixError
/// "CalculiX: 'ccx' not found in PATH (...)" when a case is for CalculiX and its program is not
/// found (both std::invalid_argument: the command line's exit 2).
void require_solvers(const std::vector<CaseSpec>& cases, const ExecutorOptions& options = {});

/// make_executor_for with `options`, as the runner's factory.
ExecutorFactory executor_factory(const ExecutorOptions& options = {});

}  // namespace cs::suites

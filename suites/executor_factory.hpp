#pragma once
// The solver boundary of the engine: a case is built once (build_problem) and solved by the
// solver its spec names. make_executor_for() is the one place that dispatches on
// CaseSpec::solver; the runner takes it as its ExecutorFactory (executor_factory(options)).
//
//   builtin   -> ProblemExecutor (suites/problem_executor.hpp), the built-in solver;
//   calculix  -> CalculixExecutor (suites/calculix_executor.hpp), ccx through the adapter;
//   external  -> ExternalExecutor (suites/external_executor.hpp), a code registered by its
//                manifest (adapters/protocol/), found by the case's solver_name;
//   imported  -> SuiteInputError: imported results are graded from a file, not run.
//
// Grading, rows, the gate and the report read the CaseResult and never learn which ran.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "suites/runner.hpp"

namespace cs::suites {

/// What an executor needs beyond the case (the external solvers' settings).
struct ExecutorOptions {
  /// Wall-clock limit of one CalculiX run in seconds (> 0); past it the case is `timeout`.
  double calculix_time_limit_seconds = 600.0;
  /// The CalculiX program (searched in PATH unless it contains '/').
  std::string ccx_executable = "ccx";
  /// Where CalculiX cases get their directories; empty: one temporary directory per process
  /// (calculix_run_directory()).
  std::filesystem::path calculix_work_root;
  /// Folders searched for external codes' manifests after the project's adapters/ and
  /// CONTACT_SUITE_SOLVER_DIRS (adapters/protocol/solver_registry.hpp).
  std::vector<std::filesystem::path> solver_dirs;
  /// Wall-clock limit of one external code's run in seconds; 0: its manifest's.
  double external_time_limit_seconds = 0.0;
  /// Where external codes' cases get their run directories; empty: a temporary directory.
  std::filesystem::path external_work_root;
};

/// The executor of the group `representative` belongs to, for the solver it names. Throws
/// SuiteInputError for imported results, and whatever building the problem throws.
std::unique_ptr<GroupExecutor> make_executor_for(const CaseSpec& representative,
                                                 const ExecutorOptions& options = {});

/// Checks, before any case runs, that every external solver `cases` name is available:
/// throws adapters::calculix::CalculixError (a std::invalid_argument: the command line's exit
/// 2) "CalculiX: 'ccx' not found in PATH (...)" when a case is for CalculiX and
/// options.ccx_executable is not found.
void require_solvers(const std::vector<CaseSpec>& cases, const ExecutorOptions& options = {});

/// make_executor_for with `options`, as the runner's factory.
ExecutorFactory executor_factory(const ExecutorOptions& options = {});

}  // namespace cs::suites

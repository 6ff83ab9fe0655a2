#pragma once
// The engine: runs a list of cases in parallel and returns one CaseResult per case, in the
// order given, whatever the number of workers.
//
// Cases that differ only in algorithm, contact discretization or contact settings share one
// model: the runner builds it once (an executor per group, made by the factory) and runs the
// variants on it one after the other, so assembly and factorization are not repeated. Groups
// are handed to workers largest first and run side by side, each on its worker's thread: the
// process's BLAS thread count is its caller's (one, for `run`), never the schedule's, so a
// group's results are never the other groups' doing. A failure — an exception from the factory or
// from an executor — becomes a `failed` result with the reason; the run goes on.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "suites/case_result.hpp"

namespace cs::suites {

/// Runs the cases of one group on a model it built once.
class GroupExecutor {
 public:
  virtual ~GroupExecutor() = default;
  /// Runs one case of the group; may throw (the runner records the failure).
  virtual CaseResult run(const CaseSpec& spec) = 0;
};

/// Builds the executor of the group that `representative` belongs to; may throw.
using ExecutorFactory = std::function<std::unique_ptr<GroupExecutor>(const CaseSpec&)>;

/// Called once per finished case (from worker threads, serialized by the runner).
using CaseCallback = std::function<void(const CaseResult&)>;

/// The settings of one run.
struct RunnerOptions {
  int jobs = 0;               ///< parallel workers; 0: the number of cores
  CaseCallback on_case_done;  ///< progress reporting; may be empty
  /// Relative cost of a group, to schedule the largest first; empty: all equal.
  std::function<double(const CaseSpec&)> group_cost;
  /// Memory-aware schedule: a group starts only while the estimated memory of the groups
  /// running plus its own stays within `memory_budget` (same units as group_memory), or when
  /// nothing else runs; otherwise the worker takes the next group (in cost order) that fits,
  /// or waits. Empty or budget <= 0: no limit. Results do not depend on the schedule.
  std::function<double(const CaseSpec&)> group_memory;
  double memory_budget = 0.0;
  /// Polled before each group: when it returns true no further group starts (an interrupt);
  /// the cases not run keep a default (failed) result. Empty: never stop.
  std::function<bool()> should_stop;
};

/// The key of the model a case runs on: the case id less algorithm, contact and the
/// contact-only parameters (fkn, ftoln, pinball).
std::string model_key(const CaseSpec& spec);

/// The cases grouped by model (model_key), as indices into `cases`: groups in the order of their
/// first case, each group's cases in the order given.
std::vector<std::vector<std::size_t>> group_by_model(const std::vector<CaseSpec>& cases);

/// Runs `cases` and returns their results in the same order.
std::vector<CaseResult> run_cases(const std::vector<CaseSpec>& cases,
                                  const ExecutorFactory& make_executor,
                                  const RunnerOptions& options);

/// The process's peak resident set size so far, in MiB.
double peak_rss_mb();

}  // namespace cs::suites

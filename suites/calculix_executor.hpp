#pragma once
// Runs the cases of one group with CalculiX (adapters/calculix/), a registered code whose
// manifest is declared beside its C++ adapter (calculix_manifest()): the problem is built once
// (build_problem, as for the built-in solver) and each case is one ccx run on it.
//
// Per case (solver external, solver_name "calculix", solver_option one of its labels):
//   1. the option: why_not_runnable() against CalculiX's manifest (an unknown label, a case id
//      whose algorithm/contact is not the option's family/discretization, a rigid target or a
//      load path: status failed, reason "not supported by calculix: ...", and ccx is not run);
//      then options_for(label, FKN, penalty_scale(model, pair, p)), K = FKN E / h for LINEAR;
//   2. ccx runs in <root>/<case id on spr, '/' and ':' as '_'> (root:
//      CalculixRunOptions::work_root or calculix_run_directory()), one thread, the time limit;
//      the directory is removed when the case converged and kept otherwise (its path ends the
//      reason); the next case of the same option on another stress basis reuses the run;
//   3. status: converged / not converged / failed / timeout as CalculiX's (run_status.hpp),
//      with its reason; a crash of ccx is that case's status, never an exception;
//   4. values (converged only), on the case's stress basis: recovery `own` = CalculiX's nodal
//      stresses (extrapolated from its integration points and averaged); spr (the `common`
//      basis) and extrapolated = our recovery of CalculiX's nodal displacements; its contact
//      pressures (CPRESS); sampled by sample_quantities() exactly as the built-in solver's are.
// wall_seconds is charged by the runner; peak_rss_mb is ccx's peak resident memory (the
// runner keeps the larger of it and this process's).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "adapters/calculix/runner.hpp"
#include "suites/problem_setup.hpp"
#include "suites/runner.hpp"

namespace cs::suites {

/// How CalculiX runs, beyond the case.
struct CalculixRunOptions {
  /// Wall-clock limit of one ccx run in seconds (> 0); past it the case is `timeout`.
  double time_limit_seconds = 600.0;
  /// The program (searched in PATH unless it contains '/'): the manifest's command.
  std::string executable = "ccx";
  /// Where cases get their directories; empty: calculix_run_directory().
  std::filesystem::path work_root;
};

class CalculixExecutor final : public GroupExecutor {
 public:
  /// Builds the problem of `representative`; throws what build_problem throws, and
  /// SuiteInputError for a time limit that is not a positive number of seconds.
  CalculixExecutor(const CaseSpec& representative, CalculixRunOptions options);
  ~CalculixExecutor() override;

  CaseResult run(const CaseSpec& spec) override;

  /// The setup the cases run on.
  const ProblemSetup& setup() const { return *setup_; }
  /// CalculiX's result of the last case's ccx run (none if it was not run). Cases that differ
  /// only in their stress basis share one run, one after the other.
  const std::optional<adapters::calculix::CalculixResult>& last_result() const { return last_; }

 private:
  std::unique_ptr<ProblemSetup> setup_;
  CalculixRunOptions options_;
  std::optional<adapters::calculix::CalculixResult> last_;
  std::string last_key_;  ///< the run directory name of the case whose run last_ holds
};

/// The directory this process's CalculiX cases run under: created on first use as
/// <temp>/contact-suite-ccx.XXXXXX (mkdtemp), the same for every later call; removed at exit
/// if it is empty (the directories of failed cases are kept).
const std::filesystem::path& calculix_run_directory();

/// The directory name of a case's ccx run: its id on the spr basis (every basis of one option
/// shares the run) with every character outside [A-Za-z0-9._=@-] as '_'.
std::string calculix_case_directory_name(const CaseSpec& spec);

}  // namespace cs::suites

#pragma once
// Runs the cases of one group with CalculiX (adapters/calculix/): the problem is built once
// (build_problem, as for the built-in solver) and each case is one ccx run on it.
//
// Per case:
//   1. options: the case's solver settings (contact_settings(spec), the built-in mapping of
//      the study's algorithm and discretization, FKN from the parameters) mapped by
//      map_contact_settings(settings, penalty_scale(model, pair, p)), K = FKN E / h;
//      mortar, MPC and a rigid target are CalculiX's gaps: status failed, reason "not
//      supported by CalculiX: ...", and ccx is not run;
//   2. ccx runs in <root>/<case id with '/' as '_'> (root: ExecutorOptions::calculix_work_root
//      or calculix_run_directory()), one thread, the options' time limit; the directory is
//      removed when the case converged and kept otherwise (its path ends the reason);
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

#include "adapters/calculix/runner.hpp"
#include "suites/executor_factory.hpp"
#include "suites/problem_setup.hpp"
#include "suites/runner.hpp"

namespace cs::suites {

class CalculixExecutor final : public GroupExecutor {
 public:
  /// Builds the problem of `representative`; throws what build_problem throws.
  CalculixExecutor(const CaseSpec& representative, const ExecutorOptions& options);
  ~CalculixExecutor() override;

  CaseResult run(const CaseSpec& spec) override;

  /// The setup the cases run on.
  const ProblemSetup& setup() const { return *setup_; }
  /// CalculiX's result of the last case that ran ccx (none if it was not run).
  const std::optional<adapters::calculix::CalculixResult>& last_result() const { return last_; }

 private:
  std::unique_ptr<ProblemSetup> setup_;
  ExecutorOptions options_;
  std::optional<adapters::calculix::CalculixResult> last_;
};

/// The directory this process's CalculiX cases run under: created on first use as
/// <temp>/contact-suite-ccx.XXXXXX (mkdtemp), the same for every later call; removed at exit
/// if it is empty (the directories of failed cases are kept).
const std::filesystem::path& calculix_run_directory();

/// The case's own directory name: its id with every character outside [A-Za-z0-9._=@-] as '_'.
std::string calculix_case_directory_name(const CaseSpec& spec);

}  // namespace cs::suites

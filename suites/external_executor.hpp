#pragma once
// Runs the cases of one group with an external code through the solver protocol
// (docs/solver-protocol.md; the code's manifest: adapters/protocol/solver_manifest.hpp).
//
// Per case:
//   1. the option: the case's solver_option must be one of the manifest's, its family's study
//      algorithm and its discretization the case's algorithm and contact fields; the analysis,
//      target and element must be in the manifest's `supports`, else status failed, reason
//      "not supported by <code>: ...", and nothing runs;
//   2. a private run directory <root>/<case>.XXXXXX holding only case/, the case directory
//      (suites/case_directory.hpp: mesh.msh, case.json);
//   3. the command, without a shell, in case/, with the manifest's (or the command line's) time
//      limit; wall time and peak memory are measured here (platform/child_process.hpp);
//   4. the status: a command that cannot start, exits non-zero, times out, writes anything into
//      the run directory beside case/ or into its own folder, or whose results cannot be read
//      (missing nodes, NaN, unparsable values: adapters/protocol/result_files.hpp) is `failed`
//      with that reason; status.json may say `not_converged`;
//   5. values, by the case's recovery (the stress basis): spr = `common`, our patch recovery
//      of the code's nodal displacements; own = the code's own nodal stresses (stresses.csv;
//      failed if it wrote none); extrapolated = our extrapolation of its displacements. The
//      contact pressure is the code's (contact_pressure.csv) where it gives one.
// A case's run directory is removed when the case converged and kept otherwise (its path ends
// the reason). Cases that differ only in their recovery share one run.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "adapters/protocol/result_files.hpp"
#include "adapters/protocol/solver_manifest.hpp"
#include "suites/problem_setup.hpp"
#include "suites/runner.hpp"
#include "suites/solver_support.hpp"

namespace cs::suites {

/// The case of an external code's option, on the model of `model_case` (its problem, mesh,
/// element, target and overrides): solver external, the option's label, family and
/// discretization, recovery `recovery`.
CaseSpec external_case(const CaseSpec& model_case, const adapters::protocol::SolverManifest& code,
                       const adapters::protocol::SolverOption& option, Recovery recovery);

/// What the external executor needs beyond the case.
struct ExternalRunOptions {
  adapters::protocol::SolverManifest manifest;
  double time_limit_seconds = 0.0;  ///< 0: the manifest's
  std::filesystem::path work_root;  ///< empty: a temporary directory per process
};

class ExternalExecutor final : public GroupExecutor {
 public:
  ExternalExecutor(const CaseSpec& representative, ExternalRunOptions options);
  ~ExternalExecutor() override;

  CaseResult run(const CaseSpec& spec) override;

  const ProblemSetup& setup() const { return *setup_; }

 private:
  struct Run;
  const Run& run_code(const CaseSpec& spec);

  std::unique_ptr<ProblemSetup> setup_;
  ExternalRunOptions options_;
  std::unique_ptr<Run> last_;
};

}  // namespace cs::suites

#include "apps/gate_command.hpp"

#include <filesystem>
#include <tuple>

#include <fmt/core.h>

#include "apps/ci_report_files.hpp"
#include "apps/usage_error.hpp"
#include "platform/output_directory.hpp"
#include "schema/baseline_file.hpp"
#include "schema/json_file.hpp"
#include "schema/results_file.hpp"
#include "suites/gate.hpp"
#include "suites/row_outcomes.hpp"

namespace cs::apps {
namespace {

struct GateArgs {
  std::string baseline, results;
  bool update = false;
  CiReportFiles ci;
};

/// The file name of a path, for the summary's title (the directories are the CI job's own).
std::string file_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

int update_baseline(const GateArgs& args, const std::vector<suites::CaseResult>& results) {
  schema::GateTolerances tolerances;
  if (std::filesystem::exists(args.baseline)) {  // keep the tolerances a team has set
    tolerances = schema::tolerances_from_json(schema::read_json_file(args.baseline, "baseline"),
                                              args.baseline);
  }
  const auto baseline = suites::make_baseline(results, tolerances);
  schema::write_baseline_file(args.baseline, baseline);
  fmt::print("gate: baseline {} updated from {} ({} cases, {} rows)\n", args.baseline, args.results,
             baseline.cases.size(), baseline.rows.size());
  return kSuccess;
}

int run_gate(const GateArgs& args) {
  if (args.update && args.ci.any())
    throw UsageError("--junit and --summary report a check; --update checks nothing");
  if (args.update)  // the baseline is written over: never the results it is made from
    platform::require_distinct(args.baseline, "--baseline", args.results, "--results");
  for (const std::string* written : {&args.ci.junit, &args.ci.summary}) {
    const char* what = written == &args.ci.junit ? "--junit" : "--summary";
    platform::require_distinct(*written, what, args.baseline, "--baseline");
    platform::require_distinct(*written, what, args.results, "--results");
  }
  require_writable(args.ci);
  const auto results = schema::read_results_file(args.results).cases;
  if (args.update)
    return update_baseline(args, results);
  const auto baseline = schema::read_baseline_file(args.baseline);
  const auto report = suites::run_gate(baseline, results);
  if (args.ci.any()) {
    write_ci_reports(args.ci, suites::gate_row_outcomes(baseline, report, results),
                     "contact-suite gate",
                     fmt::format("contact-suite gate of {} against {}", file_name(args.results),
                                 file_name(args.baseline)));
  }
  if (report.passed()) {
    fmt::print("gate: passed — {} cases and {} rows within the baseline {}\n", report.cases_checked,
               report.rows_checked, args.baseline);
    return kSuccess;
  }
  fmt::print("gate: FAILED — {} check(s) failed over {} cases and {} rows:\n\n{}",
             report.failures.size(), report.cases_checked, report.rows_checked,
             suites::format_gate_failures(report));
  return kCasesFailed;
}

}  // namespace

void add_gate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<GateArgs>();
  auto* cmd = app.add_subcommand(
      "gate", "Check results against a committed baseline: value drift, grades, convergence");
  cmd->add_option("--baseline", args->baseline, "Baseline file (ci/baseline.json)")->required();
  cmd->add_option("--results", args->results, "Results file of a run (results.json)")->required();
  cmd->add_flag("--update", args->update,
                "Rewrite the baseline from the results (keeps its tolerances)");
  add_ci_report_options(*cmd, args->ci);
  cmd->callback([args, &exit_code] { exit_code = run_gate(*args); });
}

}  // namespace cs::apps

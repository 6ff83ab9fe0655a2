#include "apps/gate_command.hpp"

#include <filesystem>
#include <tuple>

#include <fmt/core.h>

#include "apps/json_file.hpp"
#include "apps/usage_error.hpp"
#include "suites/gate.hpp"
#include "suites/results_json.hpp"

namespace cs::apps {
namespace {

struct GateArgs {
  std::string baseline, results;
  bool update = false;
};

int update_baseline(const GateArgs& args, const std::vector<suites::CaseResult>& results) {
  double default_tolerance = suites::kDefaultGateTolerance;
  std::map<std::string, double> tolerances;
  if (std::filesystem::exists(args.baseline)) {  // keep the tolerances a team has set
    std::tie(default_tolerance, tolerances) =
        suites::baseline_tolerances_from_json(read_json_file(args.baseline, "baseline"));
  }
  const auto baseline = suites::make_baseline(results, default_tolerance, tolerances);
  write_json_file_atomically(args.baseline, suites::to_json(baseline));
  fmt::print("gate: baseline {} updated from {} ({} cases, {} rows)\n", args.baseline, args.results,
             baseline.cases.size(), baseline.rows.size());
  return kSuccess;
}

int run_gate(const GateArgs& args) {
  const auto results = suites::cases_from_results_document(read_json_file(args.results, "results"));
  if (args.update)
    return update_baseline(args, results);
  const auto baseline = suites::baseline_from_json(read_json_file(args.baseline, "baseline"));
  const auto report = suites::run_gate(baseline, results);
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
  cmd->callback([args, &exit_code] { exit_code = run_gate(*args); });
}

}  // namespace cs::apps

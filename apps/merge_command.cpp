#include "apps/merge_command.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/invocation.hpp"
#include "apps/usage_error.hpp"
#include "apps/write_run_output.hpp"
#include "platform/interrupts.hpp"
#include "platform/output_directory.hpp"
#include "platform/output_transaction.hpp"
#include "schema/results_file.hpp"
#include "suites/results_merge.hpp"

namespace cs::apps {
namespace {

struct MergeArgs {
  std::string out;
  std::vector<std::string> inputs;
  bool no_report = false;
  bool mixed_builds = false;
};

int run_merge(const MergeArgs& args) {
  platform::check_output_directory(args.out);  // refused before any input is read
  for (const auto& path : args.inputs)
    platform::require_outside_set(path, args.out, "results file");
  std::vector<schema::ResultsDocument> parts;
  for (const auto& path : args.inputs)
    parts.push_back(schema::read_results_file(path));
  const auto merged = suites::merge_results(
      parts, invocation().empty() ? "contact-suite merge" : invocation(),
      args.mixed_builds ? suites::BuildMix::record : suites::BuildMix::refuse);
  platform::OutputTransaction output(args.out);  // after every check: bad input touches nothing
  if (!write_run_output(merged, output, !args.no_report)) {
    report_interrupted_write(args.out);
    return 128 + platform::interrupted_signal();
  }
  fmt::print("merge: {} cases from {} files -> {}/results.json\n", merged.cases.size(),
             parts.size(), args.out);
  for (const auto& c : merged.cases) {
    if (c.status != schema::CaseStatus::converged)
      return kCasesFailed;
  }
  return kSuccess;
}

}  // namespace

void add_merge_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<MergeArgs>();
  auto* cmd = app.add_subcommand(
      "merge", "Combine results files (the slices of `run --shard K/N`) into one, with its report");
  cmd->add_option("out", args->out, "Output directory")->required();
  cmd->add_option("results", args->inputs, "results.json files to merge")->required();
  cmd->add_flag("--no-report", args->no_report, "Write results.json only");
  cmd->add_flag("--mixed-builds", args->mixed_builds,
                "Merge files of different builds (refused otherwise) and record every build "
                "with its number of files as the merged run's contact_suite_version");
  cmd->callback([args, &exit_code] { exit_code = run_merge(*args); });
}

}  // namespace cs::apps

#include "apps/report_command.hpp"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/solver_option_mappings.hpp"
#include "platform/output_directory.hpp"
#include "platform/output_transaction.hpp"
#include "reports/report_writer.hpp"
#include "schema/combined_results.hpp"
#include "schema/results_file.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/run_environment.hpp"

namespace cs::apps {
namespace {

struct ReportArgs {
  std::vector<std::string> results;
  std::string out_dir;
  std::string baseline;
  std::string cost_run;
  std::string study_data;
  std::vector<std::string> bench;
  std::string mesh_export;
  std::vector<std::string> companions;
  bool no_figures = false;
};

void run_report(const ReportArgs& args) {
  platform::check_output_directory(args.out_dir);  // refused before any input is read
  for (const auto& path : args.results)
    platform::require_outside_set(path, args.out_dir, "--results");
  platform::require_outside_set(args.baseline, args.out_dir, "--baseline");
  platform::require_outside_set(args.cost_run, args.out_dir, "--cost-run");
  for (const auto& path : args.bench)
    platform::require_outside_set(path, args.out_dir, "--bench");
  std::vector<schema::ResultsDocument> documents;
  for (const auto& path : args.results) {
    documents.push_back(schema::read_results_file(path));
    // A file written before the records held every fact gets them from the catalogue.
    suites::refresh_problem_records(documents.back().problems);
  }
  const schema::ResultsDocument results = schema::combine_results(std::move(documents));
  std::vector<reports::CompanionReport> companions;
  for (const auto& c : args.companions)
    companions.push_back(reports::read_companion_report(args.out_dir, c));
  platform::OutputTransaction output(args.out_dir);
  reports::ReportOptions options;
  options.out_dir = output.staging_dir();
  if (!args.baseline.empty())
    options.baseline = args.baseline;
  if (!args.cost_run.empty())
    options.cost_run = args.cost_run;
  if (!args.study_data.empty())
    options.study_data = args.study_data;
  options.bench.assign(args.bench.begin(), args.bench.end());
  if (!args.mesh_export.empty())
    options.mesh_export = args.mesh_export;
  options.figures = !args.no_figures;
  options.option_mappings = solver_option_mappings();
  options.companions = std::move(companions);
  options.writer_version = suites::contact_suite_version();
  const auto outcome = reports::write_report(results, options);
  output.commit();
  std::printf("%s\n", fmt::format("contact-suite report: {} cases -> {}/report.md ({} files, {} "
                                  "figures{})",
                                  outcome.n_cases, args.out_dir, outcome.files.size(),
                                  outcome.figures_drawn,
                                  outcome.figures_missing > 0
                                      ? fmt::format(", {} not drawn", outcome.figures_missing)
                                      : std::string())
                          .c_str());
  if (!outcome.figures_unavailable.empty()) {
    std::fprintf(stderr, "contact-suite: warning: %s\n", outcome.figures_unavailable.c_str());
  }
}

}  // namespace

void add_report_command(CLI::App& app) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Write DIR/report.md (tables beside the study's, figures, findings), "
      "DIR/results.csv and, with --baseline, DIR/regression.md from a results file; with "
      "--bench, a benchmark section from bench_contact_algorithms' JSON");
  cmd->add_option("--results", args->results,
                  "results.json written by `contact-suite run` (repeatable: the files are read "
                  "as one; the first file's run is the report's run; a case or row in two "
                  "files is kept once if the two agree (values to a relative 1e-9, a case's "
                  "status exactly) and is an error if they differ)")
      ->required();
  cmd->add_option("--out", args->out_dir, "output directory (created if needed)")->required();
  cmd->add_option("--baseline", args->baseline,
                  "an older results.json: also write DIR/regression.md (grade changes, drift)");
  cmd->add_option("--cost-run", args->cost_run,
                  "results.json of ci/cost-run.sh (every code on the same models, one after "
                  "another in one run): the cross-code cost tables come from it, not from the "
                  "battery parts");
  cmd->add_option("--study-data", args->study_data,
                  "directory with the study's ansys_results.csv and ansys_grades.csv (default: "
                  "the source tree's data/study)");
  cmd->add_option("--bench", args->bench,
                  "Google Benchmark JSON written by bench_contact_algorithms "
                  "(--benchmark_out=FILE --benchmark_out_format=json): add section 8, "
                  "\"Benchmarks\" (repeatable; a case in several files is shown from the last)");
  cmd->add_option("--mesh-pictures", args->mesh_export,
                  "a directory written by `contact-suite export`: draw its models as the "
                  "report's Figure 3");
  cmd->add_option("--companion", args->companions,
                  "another report, relative to --out and written before this one (e.g. "
                  "cross-code/report.md): linked under the title with its own title "
                  "(repeatable)");
  cmd->add_flag("--no-figures", args->no_figures, "do not run gnuplot");
  cmd->callback([args] { run_report(*args); });
}

}  // namespace cs::apps

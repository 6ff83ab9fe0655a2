#include "apps/grade_command.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "adapters/protocol/solver_registry.hpp"
#include "adapters/registered_codes.hpp"
#include "apps/invocation.hpp"
#include "apps/usage_error.hpp"
#include "apps/write_run_output.hpp"
#include "platform/interrupts.hpp"
#include "platform/output_directory.hpp"
#include "platform/output_transaction.hpp"
#include "suites/import_csv.hpp"
#include "suites/imported_results.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/row_verdict.hpp"
#include "suites/run_environment.hpp"
#include "suites/runner.hpp"

namespace cs::apps {
namespace {

struct GradeArgs {
  std::string import_file;
  std::string solver_name;
  std::string target;    ///< "": as each case id says
  std::string recovery;  ///< "": as each case id says
  std::string out = "out";
  bool no_report = false;
};

/// The whole import file; UsageError if it is not a readable regular file.
std::string read_import_file(const std::string& path) {
  platform::require_printable_path(path, "--import");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw UsageError(fmt::format("--import {}: not a readable file", path));
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.good() && !in.eof())
    throw UsageError(fmt::format("--import {}: cannot be read", path));
  return text;
}

/// The target and basis the command line states (UsageError for an unknown name).
suites::ImportBasis import_basis(const GradeArgs& args) {
  suites::ImportBasis basis;
  if (!args.target.empty()) {
    basis.target = schema::try_parse<schema::TargetKind>(args.target);
    if (!basis.target)
      throw UsageError(fmt::format("--target {}: expected discretized or rigid", args.target));
  }
  if (!args.recovery.empty()) {
    basis.recovery = schema::try_parse<schema::Recovery>(args.recovery);
    if (!basis.recovery)
      throw UsageError(fmt::format(
          "--recovery {}: expected own (the code's own stresses) or spr (our patch recovery of "
          "its displacements)",
          args.recovery));
  }
  return basis;
}

int run_grade(const GradeArgs& args) {
  platform::check_output_directory(args.out);  // refused before any input is read
  platform::require_outside_set(args.import_file, args.out, "--import");
  suites::require_imported_solver_name(
      args.solver_name, adapters::registered_code_names(adapters::protocol::solver_directories()));
  const suites::ImportBasis basis = import_basis(args);
  const auto cases = suites::parse_import_csv(read_import_file(args.import_file), args.import_file);
  // Taken before grading: an unwritable or busy directory fails now; bad input found while
  // grading leaves it as it was (the transaction is not committed).
  platform::OutputTransaction output(args.out);
  schema::RunInfo info;
  info.started_utc = suites::utc_now_iso8601();
  info.command_line = invocation().empty() ? "contact-suite grade" : invocation();
  info.environment = suites::run_environment();
  const auto start = std::chrono::steady_clock::now();
  const auto results = suites::grade_imported(cases, args.solver_name, args.import_file, basis);
  info.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  info.peak_rss_mb = suites::peak_rss_mb();
  const schema::ResultsDocument doc{.source = {},
                                    .run = info,
                                    .problems = suites::problem_records(results),
                                    .cases = results,
                                    .rows = suites::make_row_verdicts(results),
                                    .added_runs = {},
                                    .parameter_defaults = suites::parameter_defaults(results)};
  const auto figures = write_run_output(doc, output, !args.no_report);
  if (!figures) {
    report_interrupted_write(args.out);
    return 128 + platform::interrupted_signal();
  }
  fmt::print("graded {} cases of {}: wrote {}{}\n", results.size(), args.solver_name,
             (std::filesystem::path(args.out) / "results.json").string(),
             args.no_report ? "" : fmt::format(" and its report ({} figures)", *figures));
  return kSuccess;
}

}  // namespace

void add_grade_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<GradeArgs>();
  auto* cmd = app.add_subcommand(
      "grade",
      "Grade another code's results (the import layout of docs/import-export.md) like a run");
  cmd->add_option("--import", args->import_file,
                  "CSV of case_id,x,sigma_z,sigma_x,contact_pressure and optionally option, "
                  "wall_seconds, iterations, n_equations, peak_rss_mb (docs/import-export.md)")
      ->required();
  cmd->add_option("--target", args->target,
                  "The target of every case: discretized or rigid (default: as each case id "
                  "says; an id that says otherwise is refused)");
  cmd->add_option("--recovery", args->recovery,
                  "The stress basis of every case: own (the code's own nodal stresses) or spr "
                  "(our patch recovery of its displacements); default: as each case id says");
  cmd->add_option("--solver-name", args->solver_name,
                  "The code that produced the results, e.g. abaqus-2024 ([A-Za-z0-9._-])")
      ->required();
  cmd->add_option("--out", args->out, "Output directory")->capture_default_str();
  cmd->add_flag("--no-report", args->no_report, "Write results.json only");
  cmd->callback([args, &exit_code] { exit_code = run_grade(*args); });
}

}  // namespace cs::apps

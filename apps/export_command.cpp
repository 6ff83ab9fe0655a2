#include "apps/export_command.hpp"

#include <cstdio>
#include <memory>

#include <fmt/core.h>

#include "apps/case_selection_options.hpp"
#include "apps/usage_error.hpp"
#include "apps/write_run_output.hpp"
#include "platform/interrupts.hpp"
#include "platform/output_transaction.hpp"
#include "suites/model_export.hpp"
#include "suites/runner.hpp"

namespace cs::apps {
namespace {

struct ExportArgs {
  SelectionArgs selection;
  std::string out = "export";
};

int run_export(const ExportArgs& args) {
  platform::check_output_directory(args.out);  // refused before any input is read
  const auto cases = suites::make_case_matrix(make_selection(args.selection));
  validate_cases(cases);
  for (const auto& spec : cases)
    suites::require_exchangeable(spec);
  platform::OutputTransaction output(args.out);
  std::string cases_csv = suites::cases_csv_header();
  const auto groups = suites::group_by_model(cases);
  for (const auto& members : groups) {
    if (const int sig = platform::interrupted_signal(); sig != 0) {
      std::fprintf(stderr, "contact-suite: interrupted by signal %d; %s left as it was\n", sig,
                   args.out.c_str());
      return 128 + sig;
    }
    const suites::CaseSpec& representative = cases[members.front()];
    const std::string dir = "models/" + suites::model_directory_name(representative);
    const suites::ProblemSetup setup = suites::build_problem(representative);
    for (const auto& file : suites::model_files(setup))
      output.write_text(dir + "/" + file.name, file.text);
    for (std::size_t i : members)
      cases_csv += suites::cases_csv_rows(cases[i], setup, dir);
  }
  output.write_text("cases.csv", cases_csv);
  output.commit();
  fmt::print("wrote {} cases on {} models to {}\n", cases.size(), groups.size(), args.out);
  return kSuccess;
}

}  // namespace

void add_export_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ExportArgs>();
  auto* cmd = app.add_subcommand(
      "export",
      "Write the selected cases as documented CSV (mesh, sets, loads, materials, contact pair, "
      "what to sample) for another code; see docs/import-export.md");
  add_selection_options(*cmd, args->selection);
  cmd->add_option("--out", args->out, "Output directory")->capture_default_str();
  cmd->callback([args, &exit_code] { exit_code = run_export(*args); });
}

}  // namespace cs::apps

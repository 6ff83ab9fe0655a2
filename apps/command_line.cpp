#include "apps/command_line.hpp"

#include <cstdio>
#include <exception>
#include <string>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "apps/case_command.hpp"
#include "apps/export_command.hpp"
#include "apps/gate_command.hpp"
#include "apps/grade_command.hpp"
#include "apps/invocation.hpp"
#include "apps/list_command.hpp"
#include "apps/merge_command.hpp"
#include "apps/oracle_command.hpp"
#include "apps/report_command.hpp"
#include "apps/run_command.hpp"
#include "apps/usage_error.hpp"
#include "platform/interrupts.hpp"
#include "platform/platform_error.hpp"
#include "schema/schema_error.hpp"
#include "suites/run_environment.hpp"
#include "suites/start_settings.hpp"

namespace cs::apps {
namespace {

std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r')
      c = ' ';
  }
  while (!text.empty() && text.back() == ' ')
    text.pop_back();
  return text;
}

/// Whether the subcommand is one that builds and factorizes models (`run`, `case`).
bool solves_models(int argc, char** argv) {
  const std::string command = argc > 1 ? argv[1] : "";
  return command == "run" || command == "case";
}

}  // namespace

int run_command_line(int argc, char** argv) {
  // May execute the program again, once; huge pages for the commands that solve models.
  cs::suites::start_with_the_machines_settings(argv, {.huge_pages = solves_models(argc, argv)});
  cs::suites::run_openmp_regions_serially();
  CLI::App app{
      "contact-suite: frictionless contact problems with exact solutions, solved by finite "
      "elements and graded against the exact answer"};
  app.require_subcommand(1);
  int exit_code = kSuccess;
  for (int i = 0; i < argc; ++i) {
    invocation() += (i ? " " : "") + std::string(i ? argv[i] : "contact-suite");
  }
  add_oracle_command(app);
  add_list_command(app);
  add_case_command(app, exit_code);
  add_run_command(app, exit_code);
  add_report_command(app);
  add_gate_command(app, exit_code);
  add_merge_command(app, exit_code);
  add_export_command(app, exit_code);
  add_grade_command(app, exit_code);

  // Ctrl-C and SIGTERM stop us and every child (gnuplot, ccx) together; commands poll
  // interrupted_signal() between units of work and exit 128 + signal without committing output.
  cs::platform::install_interrupt_forwarding();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "contact-suite: error: %s\n", one_line(e.what()).c_str());
    return kBadInput;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "contact-suite: error: %s\n", one_line(e.what()).c_str());
    return kBadInput;
  } catch (const cs::schema::SchemaError& e) {
    std::fprintf(stderr, "contact-suite: error: %s\n", one_line(e.what()).c_str());
    return kBadInput;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "contact-suite: error: %s\n", one_line(e.what()).c_str());
    return kBadInput;
  } catch (const cs::platform::OutputError& e) {  // e.g. no space left on the device
    std::fprintf(stderr, "contact-suite: error: %s\n", one_line(e.what()).c_str());
    return kOutputFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contact-suite: internal error: %s\n", one_line(e.what()).c_str());
    return 3;
  }
  if (const int sig = cs::platform::interrupted_signal(); sig != 0 && exit_code == 0)
    return 128 + sig;
  return exit_code;
}

}  // namespace cs::apps

#include "apps/write_run_output.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include <fmt/core.h>

#include "apps/solver_option_mappings.hpp"
#include "platform/interrupts.hpp"
#include "reports/report_writer.hpp"
#include "schema/json_file.hpp"
#include "suites/run_environment.hpp"

namespace cs::apps {

std::optional<int> write_run_output(const schema::ResultsDocument& doc,
                                    platform::OutputTransaction& out, bool with_report) {
  schema::write_results_file(out.staging_dir() / "results.json", doc);
  int figures = 0;
  if (with_report) {
    reports::ReportOptions report;
    report.out_dir = out.staging_dir();
    report.option_mappings = solver_option_mappings();
    report.writer_version = suites::contact_suite_version();
    schema::ResultsDocument named = doc;  // the report names the file it describes
    std::error_code ec;
    const auto shown = std::filesystem::relative(out.directory(), ec);
    named.source = ((ec || shown.empty() ? out.directory() : shown) / "results.json").string();
    const auto outcome = reports::write_report(named, report);
    figures = outcome.figures_drawn;
    if (!outcome.figures_unavailable.empty())
      std::fprintf(stderr, "contact-suite: warning: %s\n", outcome.figures_unavailable.c_str());
  }
  // Interrupted while the report was built (gnuplot stopped with us, its figures missing):
  // commit nothing, so the directory keeps its complete previous set.
  if (platform::interrupted_signal() != 0)
    return std::nullopt;
  out.commit();
  return figures;
}

void report_interrupted_write(const std::string& out_dir) {
  std::fprintf(stderr, "contact-suite: interrupted: %s left as it was\n", out_dir.c_str());
}

}  // namespace cs::apps

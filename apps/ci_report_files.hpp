#pragma once
// `--junit FILE` and `--summary FILE` of `run` and `gate`: the rows as JUnit XML for a CI
// system's test report (apps/junit_xml.hpp), and a Markdown summary appended to FILE for a
// CI job's summary page, e.g. --summary "$GITHUB_STEP_SUMMARY" (apps/ci_summary.hpp).

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "schema/row_outcome.hpp"

namespace cs::apps {

/// The files asked for (empty: not asked).
struct CiReportFiles {
  std::string junit;
  std::string summary;
  bool any() const { return !junit.empty() || !summary.empty(); }
};

/// Adds --junit and --summary to `cmd`.
void add_ci_report_options(CLI::App& cmd, CiReportFiles& files);

/// Throws UsageError ("--junit F: ...") unless every file asked for can be written: its
/// directory exists and a file can be created (or appended to) there; PlatformError when the
/// two are one file or one lies among the set of an output directory of contact-suite. Called
/// before a run starts, so that a typo in a path costs nothing. Leaves no file behind.
void require_writable(const CiReportFiles& files);

/// Writes the JUnit file (replacing it atomically: complete old or complete new) and appends
/// the summary. `name` names the JUnit root ("contact-suite gate"), `title` heads the summary.
/// Throws UsageError when a file cannot be written.
void write_ci_reports(const CiReportFiles& files, const std::vector<schema::RowOutcome>& rows,
                      std::string_view name, std::string_view title);

}  // namespace cs::apps

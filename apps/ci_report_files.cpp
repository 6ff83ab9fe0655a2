#include "apps/ci_report_files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <fmt/core.h>

#include "apps/ci_summary.hpp"
#include "apps/junit_xml.hpp"
#include "apps/usage_error.hpp"
#include "platform/output_directory.hpp"
#include "platform/replaceable_file.hpp"

namespace cs::apps {
namespace {

namespace fs = std::filesystem;

/// How a JUnit file of an earlier version (before the mark) began: its root element.
constexpr std::string_view kOlderJunitMark = R"(<testsuites name="contact-suite )";

fs::path directory_of(const fs::path& file) {
  return file.has_parent_path() ? file.parent_path() : fs::path(".");
}

/// Throws unless `path` (of `option`) names a file that can be created or appended to.
void require_writable_file(const std::string& option, const std::string& path) {
  if (path.empty())
    return;
  std::error_code ec;
  const fs::path file(path);
  if (fs::is_directory(file, ec))
    throw UsageError(fmt::format("{} {}: is a directory, not a file", option, path));
  const fs::path dir = directory_of(file);
  if (!fs::is_directory(dir, ec))
    throw UsageError(
        fmt::format("{} {}: the directory {} does not exist", option, path, dir.string()));
  // A dangling link is the user's: appending through it would create its target, and removing
  // the probe afterwards would delete the link.
  const fs::file_status link = fs::symlink_status(file, ec);
  if (fs::is_symlink(link) && !fs::exists(file, ec))
    throw UsageError(
        fmt::format("{} {}: a link to a missing file; not written through", option, path));
  const bool existed = fs::exists(link);
  std::FILE* f = std::fopen(path.c_str(), "a");
  if (f == nullptr) {
    throw UsageError(
        fmt::format("{} {}: cannot be written ({})", option, path, std::strerror(errno)));
  }
  std::fclose(f);
  if (!existed)
    fs::remove(file, ec);
}

void append_file(const std::string& option, const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::app);
  out << text;
  out.close();
  if (!out)
    throw UsageError(fmt::format("{} {}: cannot be written", option, path));
}

}  // namespace

void add_ci_report_options(CLI::App& cmd, CiReportFiles& files) {
  // An empty name would read as "not asked" and write nothing, silently. --summary keeps that
  // reading: `--summary "$GITHUB_STEP_SUMMARY"` outside GitHub Actions asks for nothing.
  const CLI::Validator named(
      [](const std::string& path) { return path.empty() ? "an empty file name" : ""; }, "FILE");
  cmd.add_option("--junit", files.junit,
                 "Also write the rows as JUnit XML for a CI test report: one testsuite per "
                 "problem, one testcase per row")
      ->check(named);
  cmd.add_option("--summary", files.summary,
                 "Also append a Markdown summary (counts, rows that did not pass or moved) to "
                 "this file, e.g. \"$GITHUB_STEP_SUMMARY\" (empty: none)");
}

void require_writable(const CiReportFiles& files) {
  platform::require_distinct(files.junit, "--junit", files.summary, "--summary");
  platform::require_outside_sets(files.junit, "--junit");
  platform::require_outside_sets(files.summary, "--summary");
  // First, so that a link or a FIFO is refused before it is opened. A file of an earlier version
  // (before the mark) began with its root element, named by write_ci_reports' callers.
  platform::require_replaceable(files.junit, "--junit", kOlderJunitMark);
  require_writable_file("--junit", files.junit);
  require_writable_file("--summary", files.summary);
}

void write_ci_reports(const CiReportFiles& files, const std::vector<schema::RowOutcome>& rows,
                      std::string_view name, std::string_view title) {
  if (!files.junit.empty())
    platform::replace_written_file(files.junit, junit_xml(rows, name), "--junit", kOlderJunitMark);
  if (!files.summary.empty())
    append_file("--summary", files.summary, ci_summary_markdown(rows, title));
}

}  // namespace cs::apps

#include "reports/companion_report.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

#include <fmt/format.h>

#include "reports/render/template_text.hpp"
#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

constexpr std::string_view kTitlePrefix = "# ";
constexpr std::string_view kProjectPrefix = "contact-suite report: ";
/// report.mustache's last line: "*Written by contact-suite 0.1.0+cc88371.*".
constexpr std::string_view kWriterPrefix = "*Written by contact-suite ";
constexpr std::string_view kWriterSuffix = ".*";

/// The build named by a report's last non-empty line, its "Written by" line, or empty.
std::string writer_of(std::istream& in) {
  std::string line, last;
  while (std::getline(in, line)) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back())))
      line.pop_back();  // a "\r" of a file saved with CRLF, or trailing blanks
    if (!line.empty())
      last = std::move(line);
  }
  if (last.size() <= kWriterPrefix.size() + kWriterSuffix.size() ||
      !last.starts_with(kWriterPrefix) || !last.ends_with(kWriterSuffix))
    return {};
  return last.substr(kWriterPrefix.size(),
                     last.size() - kWriterPrefix.size() - kWriterSuffix.size());
}

bool safe_link_path(const std::string& p) {
  const bool chars = std::all_of(p.begin(), p.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '.' || c == '_' || c == '/' || c == '-';
  });
  const std::filesystem::path path(p);
  const bool climbs = std::any_of(path.begin(), path.end(),
                                  [](const std::filesystem::path& part) { return part == ".."; });
  return chars && !p.empty() && !path.is_absolute() && !climbs && path.extension() == ".md";
}

}  // namespace

CompanionReport read_companion_report(const std::filesystem::path& report_dir,
                                      const std::string& relative) {
  if (!safe_link_path(relative)) {
    throw ReportError(fmt::format(
        "--companion '{}': expected a path to a .md file under the report's directory, of "
        "letters, digits, '.', '_', '-' and '/', without '..'",
        relative));
  }
  const std::filesystem::path file = report_dir / relative;
  std::ifstream in(file);
  std::string first;
  if (!in || !std::getline(in, first)) {
    throw ReportError(fmt::format("--companion '{}': cannot read {} (write that report first)",
                                  relative, file.string()));
  }
  if (first.rfind(kTitlePrefix, 0) != 0 || first.find_first_of("[]`") != std::string::npos) {
    throw ReportError(fmt::format(
        "--companion '{}': its first line is not a report title (\"# ...\", without '[', ']' "
        "or '`')",
        relative));
  }
  std::string title = first.substr(kTitlePrefix.size());
  if (title.rfind(kProjectPrefix, 0) == 0)
    title = title.substr(kProjectPrefix.size());
  return {relative, title, writer_of(in)};
}

std::string companions_markdown(const std::vector<CompanionReport>& companions,
                                const std::string& writer) {
  if (companions.empty())
    return {};
  TemplateData d("companions", template_list(companions, [&](const CompanionReport& c) {
                   TemplateData e("title", c.title);
                   e.set("path", c.path);
                   e.set("other_build", !writer.empty() && c.writer != writer);
                   e.set("writer", text_or_false(c.writer));
                   return e;
                 }));
  return render_template(templates::companion_links, d);
}

}  // namespace cs::reports

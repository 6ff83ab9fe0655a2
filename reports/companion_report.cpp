#include "reports/companion_report.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

#include <fmt/format.h>

#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

constexpr std::string_view kTitlePrefix = "# ";
constexpr std::string_view kProjectPrefix = "contact-suite report: ";

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
  return {relative, title};
}

std::string companions_markdown(const std::vector<CompanionReport>& companions) {
  std::string out;
  for (const auto& c : companions)
    out += fmt::format("Also: [{}]({}).\n\n", c.title, c.path);
  return out;
}

}  // namespace cs::reports

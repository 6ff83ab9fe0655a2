#pragma once
// Another report linked from a report's header (`report --companion cross-code/report.md`): the
// committed study report points its reader to the cross-code report written beside it. The
// link's text is the companion's own title, read from its first line, so the link says what the
// other report is without being typed in.

#include <filesystem>
#include <string>
#include <vector>

namespace cs::reports {

struct CompanionReport {
  std::string path;    ///< relative to the linking report's directory: "cross-code/report.md"
  std::string title;   ///< its title less "contact-suite report: "
  std::string writer;  ///< the build that wrote it, from its "Written by" line; empty: unrecorded
};

/// Reads the companion `relative` (to `report_dir`). Throws ReportError, naming the cause, for a
/// path that is absolute, climbs out with "..", has characters outside [A-Za-z0-9._/-] (it
/// becomes a Markdown link) or does not end in ".md"; for a file that does not exist or cannot
/// be read; for a first line that is not a "# " title or holds "[", "]" or a backtick.
CompanionReport read_companion_report(const std::filesystem::path& report_dir,
                                      const std::string& relative);

/// "Also: [title](path)." lines, one per companion, and a blank line; empty for none. A companion
/// not written by `writer` (this report's build; empty: unknown, no note) says whose rules its
/// verdicts follow (templates/companion_links.mustache).
std::string companions_markdown(const std::vector<CompanionReport>& companions,
                                const std::string& writer);

}  // namespace cs::reports

#pragma once
// Single files the tool writes where the user names them (--junit, --vtu). Such a file may
// replace only a file the tool wrote earlier: those carry written_mark(), an XML comment, near
// their top. Anything else at that path is the user's and is refused before any work starts,
// so nothing the user had is lost.

#include <filesystem>
#include <string>
#include <string_view>

namespace cs::platform {

/// The text of the XML comment that marks a single file as written by contact-suite.
inline constexpr std::string_view kWrittenMarkText = " written by contact-suite ";

/// The comment itself, as it stands in the file: `<!--` kWrittenMarkText `-->`.
std::string written_mark();

/// Throws PlatformError when `file` (given as option `what`) exists and the tool did not write
/// it: it is not a regular file (a link, a directory, a FIFO, ...), or its first
/// kWrittenMarkReach bytes hold neither written_mark() nor `older_mark` (when not empty: how
/// files of the kind began before they carried the mark).
void require_replaceable(const std::filesystem::path& file, const char* what,
                         std::string_view older_mark = {});

/// How far into a file require_replaceable looks for the mark.
inline constexpr std::size_t kWrittenMarkReach = 512;

/// Writes `text` as `file` (given as option `what`) in one step: a temporary file beside it,
/// then a rename. The check of require_replaceable is made again at the rename, not only when
/// the run started: a file the user put there meanwhile is kept, and the call throws
/// PlatformError (nothing is written). An absent file is created only if it is still absent
/// (renameat2's RENAME_NOREPLACE; where the file system lacks it, the check just before the
/// rename). Throws OutputError when the file system fails (e.g. no space left).
void replace_written_file(const std::filesystem::path& file, std::string_view text,
                          const char* what, std::string_view older_mark = {});

}  // namespace cs::platform

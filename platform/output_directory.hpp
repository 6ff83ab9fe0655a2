#pragma once
// Output directories the tool owns: which directories contact-suite may write into.
//
// A directory is contact-suite's when it holds the ownership mark, a regular file named
// `.contact-suite` whose text names the output format ("contact-suite output directory",
// "format 1"; an empty mark counts as format 1, so that a user can hand an older output
// directory over with `touch DIR/.contact-suite`). The tool writes into
//   - a directory that does not exist yet, when its parent exists and is writable (it creates
//     it and marks it);
//   - an existing empty directory (it marks it, and never changes its owner or mode);
//   - a directory carrying the mark, of this format or an older one.
// Anything else is refused with a PlatformError (exit code 2: one line naming the directory and
// what to do), before anything is written: a non-empty directory without the mark (so `--out /`,
// `--out ~` and `--out .` on a non-empty tree), a file, a symbolic link to a directory without
// the mark, a missing or unwritable parent, a path with control characters. The check reads
// only the directory's own entry, its parent's, its mark and at most its first entry: it never
// walks a tree.

#include <filesystem>
#include <string>

namespace cs::platform {

/// The name of the ownership mark inside an output directory. Every entry whose name starts
/// with it (`.contact-suite.staging-PID`, `.contact-suite.commit`, ...) is the tool's
/// bookkeeping, never part of a result set.
inline constexpr const char* kOwnershipMark = ".contact-suite";

/// The output format this build writes into the mark; a mark of a newer format is refused.
inline constexpr int kOutputFormat = 1;

/// What a checked output directory is now.
enum class OutputDirectoryState {
  absent,  ///< does not exist; its parent exists and is writable
  empty,   ///< exists, empty, writable
  owned    ///< exists, carries the mark, writable
};

/// The result of check_output_directory.
struct OutputDirectory {
  std::filesystem::path path;  ///< absolute and normalized; a symbolic link resolved
  OutputDirectoryState state = OutputDirectoryState::absent;
};

/// Checks that contact-suite may write into `dir` (see the file comment) without writing
/// anything. Throws PlatformError naming the directory and what to do.
OutputDirectory check_output_directory(const std::filesystem::path& dir);

/// The text of the mark this build writes.
std::string ownership_mark_text();

/// True when `name` (one path component) is the mark or the tool's bookkeeping beside it.
bool is_bookkeeping_name(const std::string& name);

/// Throws PlatformError when `file` (given as option `what`, e.g. "--results") is or may become
/// an entry of the set of the output directory `dir`: a file directly in `dir`, or below a
/// directory its set lists (figures/, models/). An input there may be an entry the new set
/// removes, and a file written there would overwrite the set. Files in the user's own
/// subdirectories (e.g. a Slurm run's shard-K/) are not the set's.
void require_outside_set(const std::filesystem::path& file, const std::filesystem::path& dir,
                         const char* what);

/// require_outside_set for every directory holding `file` that carries the mark: for a file the
/// command writes itself (--junit, --summary, --vtu).
void require_outside_sets(const std::filesystem::path& file, const char* what);

/// Throws PlatformError when the files `a` and `b` (options `what_a` and `what_b`) are one file.
void require_distinct(const std::filesystem::path& a, const char* what_a,
                      const std::filesystem::path& b, const char* what_b);

/// Throws PlatformError if `path` holds a control character (newline, tab, escape, ...): such
/// names break every line-oriented consumer (scripts, logs, plot files) and are refused.
void require_printable_path(const std::filesystem::path& path, const char* what);

}  // namespace cs::platform

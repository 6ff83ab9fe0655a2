#pragma once
// An output directory written as one transaction: a run's results.json, results.csv, report.md
// and figures appear together or not at all, in a directory the tool owns
// (platform/output_directory.hpp), without touching anything else in it.
//
//   OutputTransaction out("out");     // checks and takes the directory, opens a staging area
//   write files under out.staging_dir() (or out.write_text(...)): the complete new set
//   out.commit();                     // moves the set into place
//
// Everything lives inside the directory (nothing is created beside it):
//   .contact-suite                 the ownership mark, and the lock: an exclusive flock(2) on
//                                  it, held from construction to destruction (the kernel drops
//                                  it when the process dies). A second writer gets a
//                                  PlatformError unless asked to wait.
//   .contact-suite.set             the names of the entries of the committed set, one a line
//   .contact-suite.staging-PID/    where the new set is written
//   .contact-suite.commit/         a complete set being moved into place (the commit journal)
//   .contact-suite.old/            entries of the previous set being removed
// The commit: the staging directory, with the list of its entries, is renamed to
// `.contact-suite.commit` in one atomic step: from then on the new set is decided. Its entries
// are then renamed into place one by one, results.json last (a file replaces its predecessor
// atomically; a directory such as figures/ first moves its predecessor aside), entries of the
// previous set that the new one lacks are moved aside, and the list is installed. Whoever opens
// the directory next finds an interrupted commit by its journal and finishes it before anything
// else, so after a kill at any moment the directory holds the complete old set, or the complete
// new set once the journal (present only for the microseconds of the renames) is rolled forward.
// Entries the tool did not write (a user's notes, subdirectories, mount points) are never
// moved, re-created, re-owned or re-moded: they keep their inode.
// Without commit(), the destructor removes the staging directory, and the mark and the
// directory too when this transaction created them: a refused or failed run leaves nothing.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "platform/output_directory.hpp"

namespace cs::platform {

class OutputTransaction {
 public:
  /// Checks `dir` (check_output_directory), creates and marks it when needed, takes its lock
  /// (waiting for it when `wait`, else failing at once), finishes an interrupted commit,
  /// removes stale staging directories of killed runs and creates a fresh one. Throws
  /// PlatformError for a directory it may not use or one another process holds, and
  /// OutputError when the file system fails (e.g. no space left).
  explicit OutputTransaction(std::filesystem::path dir, bool wait = false);
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  /// Where the new set is written (empty at first but for its own mark).
  const std::filesystem::path& staging_dir() const { return staging_; }
  /// The output directory, absolute (a symbolic link to it resolved).
  const std::filesystem::path& directory() const { return dir_; }

  /// Writes a whole text file `relative` (e.g. "figures/a.gp") under staging_dir(), creating
  /// its parent directories; throws OutputError naming the file and the cause.
  void write_text(const std::string& relative, std::string_view content) const;

  /// Makes the staged set the directory's set (see above). Returns the committed regular files
  /// relative to the directory, sorted. Throws OutputError when a rename fails (the next
  /// transaction on the directory finishes the commit).
  std::vector<std::string> commit();

 private:
  void take_directory(bool wait);
  void release_on_failure();

  std::filesystem::path shown_;  ///< the directory as given, for messages
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  int lock_fd_ = -1;
  bool created_dir_ = false;
  bool created_mark_ = false;
  bool committed_ = false;
};

}  // namespace cs::platform

#pragma once
// An output directory written as one transaction: a run's results.json, results.csv, report.md
// and figures appear together or not at all.
//
//   OutputTransaction out("out");     // takes the directory's lock, clears stale staging
//   write files under out.staging();  // the complete new set
//   out.commit();                     // swaps it in atomically
//
// The lock: an exclusive flock(2) on `<parent>/.<name>.lock`, held from construction to
// destruction (the kernel drops it if the process dies). A second writer gets a PlatformError
// ("another contact-suite process is writing to 'out'") unless asked to wait.
// The staging directory `<parent>/.<name>.staging-<pid>` is a sibling of the output directory
// (same file system). commit() first hard-links into it every entry of the existing directory
// that the new set does not replace (so nothing a user kept there is lost), then exchanges the
// two directories with renameat2(RENAME_EXCHANGE), one atomic step, and removes the old set.
// A kill at any moment leaves `out` holding either the complete old set or the complete new
// set; the leftover staging directory is removed by the next transaction on `out`.
// Without commit(), the destructor removes the staging directory and `out` is untouched.

#include <filesystem>

namespace cs::platform {

class OutputTransaction {
 public:
  /// Takes the lock of `dir` (waiting for it when `wait`, else failing at once), removes stale
  /// staging directories of earlier interrupted runs and creates a fresh one. Throws
  /// PlatformError naming the cause: a path with control characters, a parent that does not
  /// exist or is not writable, `dir` being a file, the lock held by another process.
  explicit OutputTransaction(std::filesystem::path dir, bool wait = false);
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  /// Where the new set is written (an empty directory at first).
  const std::filesystem::path& staging() const { return staging_; }
  const std::filesystem::path& directory() const { return dir_; }

  /// Makes the staged set the content of the directory (see above). Throws PlatformError.
  void commit();

 private:
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  std::filesystem::path created_lock_;  ///< the lock file, when this transaction created it
  int lock_fd_ = -1;
  bool committed_ = false;
};

/// Throws PlatformError if `path` holds a control character (newline, tab, escape, ...): such
/// names break every line-oriented consumer (scripts, logs, plot files) and are refused.
void require_printable_path(const std::filesystem::path& path, const char* what);

}  // namespace cs::platform

#pragma once
// A process's scratch directory for the cases another code solves: created under the temporary
// directory (TMPDIR) on first use, and removed at exit when it is empty, i.e. when every case's
// own directory was removed after its run. A failed case keeps its files there (its reason names
// them), and so does the directory.

#include <filesystem>
#include <string>

namespace cs::suites {

/// Throws SuiteInputError (one line naming TMPDIR) unless the temporary directory is a directory
/// this process may create entries in: checked before another code's cases run.
void require_temporary_directory();

class RunDirectory {
 public:
  /// Creates <temporary directory>/<prefix>.XXXXXX. Throws std::system_error if it cannot.
  explicit RunDirectory(const std::string& prefix);
  ~RunDirectory();
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace cs::suites

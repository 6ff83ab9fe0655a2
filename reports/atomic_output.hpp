#pragma once
// Writing a set of report files so that nothing is ever half-written: every file is first
// written under DIR/.tmp-XXXXXX (same file system, so rename is atomic), then renamed into
// place by commit(). Until commit(), DIR's existing content is untouched; if the object is
// destroyed without commit() (an error on the way), the temporary directory is removed, and
// DIR itself too when this object created it and it is still empty.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cs::reports {

class AtomicOutput {
 public:
  /// Creates `dir` if needed and a staging directory inside it; throws ReportError when
  /// either cannot be created (e.g. `dir` is a file, or not writable).
  explicit AtomicOutput(std::filesystem::path dir);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  /// The staging path of a file (relative to `dir`, e.g. "figures/a.png"), its parent created;
  /// whatever is written there is moved into `dir` by commit().
  std::filesystem::path staging_path(const std::string& relative) const;
  /// The staging directory itself (files written under it are committed).
  const std::filesystem::path& staging_dir() const { return staging_; }

  /// Writes a whole text file into staging; throws ReportError on an I/O error.
  void write_text(const std::string& relative, std::string_view content);

  /// Renames every staged file into `dir` (replacing older files of the same name) and removes
  /// the staging directory. Returns the committed files relative to `dir`, sorted.
  std::vector<std::string> commit();

 private:
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  bool created_dir_ = false;
  bool committed_ = false;
};

}  // namespace cs::reports

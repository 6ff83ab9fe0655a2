#pragma once
// Running gnuplot (Debian's gnuplot-nox) on a script file: finding it, choosing its PNG
// terminal (pngcairo, else the libgd png), a scratch directory for its data and scripts, and
// quoting for its single-quoted strings.

#include <filesystem>
#include <optional>
#include <string>

namespace cs::reports {

/// A usable gnuplot: the program and the PNG terminal it offers.
struct Gnuplot {
  std::string program;   ///< as given, e.g. "gnuplot" (found on PATH)
  std::string terminal;  ///< "pngcairo" or "png"
};

/// Probes `program`: nullopt when it cannot be run or offers neither PNG terminal.
std::optional<Gnuplot> find_gnuplot(const std::string& program = "gnuplot");

/// Runs `script` with its output in `log`; returns an empty string on success, else a one-line
/// description (exit status and the first error line of the log).
std::string run_gnuplot(const Gnuplot& gnuplot, const std::filesystem::path& script,
                        const std::filesystem::path& log);

/// A temporary directory for gnuplot's data files and scripts, removed with its content when
/// the object goes out of scope.
class ScratchDir {
 public:
  /// Creates a fresh directory under the system's temporary directory; throws
  /// std::runtime_error when it cannot.
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// `text` as a gnuplot single-quoted string literal ('' stands for a quote inside).
std::string gnuplot_quote(const std::string& text);

}  // namespace cs::reports

#include "reports/figures/gnuplot.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "platform/child_process.hpp"
#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

/// gnuplot runs as a child with an argument vector, never through a shell; SIGINT/SIGTERM to us
/// reach it too (platform/interrupts.hpp).
platform::ChildResult run(std::vector<std::string> argv, const std::filesystem::path& log) {
  platform::ChildOptions options;
  options.argv = std::move(argv);
  options.stdout_path = log;
  options.stderr_path = log.empty() ? std::filesystem::path() : log;
  options.time_limit_seconds = 120;
  return platform::run_child(options);
}

bool offers_terminal(const std::string& program, const std::string& terminal) {
  return run({program, "-e", "set terminal " + terminal}, {}).succeeded();
}

bool has_control_character(const std::string& text) {
  return std::any_of(text.begin(), text.end(),
                     [](unsigned char c) { return c < 0x20 || c == 0x7f; });
}

}  // namespace

std::optional<Gnuplot> find_gnuplot(const std::string& program) {
  for (const char* terminal : {"pngcairo", "png"}) {
    if (offers_terminal(program, terminal))
      return Gnuplot{program, terminal};
  }
  return std::nullopt;
}

std::string run_gnuplot(const Gnuplot& gnuplot, const std::filesystem::path& script,
                        const std::filesystem::path& log) {
  const platform::ChildResult result = run({gnuplot.program, script.string()}, log);
  if (result.succeeded())
    return {};
  if (result.exit_code < 0)
    return "gnuplot " + result.describe();
  const int status = result.exit_code;
  std::ifstream in(log);
  std::string line, first_error;
  while (std::getline(in, line)) {
    if (line.find("line ") != std::string::npos || line.find("rror") != std::string::npos) {
      first_error = line;
      break;
    }
  }
  return fmt::format("gnuplot exited with status {}{}", status,
                     first_error.empty() ? "" : ": " + first_error);
}

ScratchDir::ScratchDir() {
  // Scripts name files in this directory: a TMPDIR with a control character is not used.
  std::filesystem::path base = std::filesystem::temp_directory_path();
  if (has_control_character(base.string()))
    base = "/tmp";
  std::string pattern = (base / "cs-report-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a temporary directory");
  path_ = pattern;
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string gnuplot_quote(const std::string& text) {
  // A newline would end the gnuplot command and start another: such text is refused.
  if (has_control_character(text))
    throw ReportError("figure: a path or label holds a control character; not written to a script");
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "''";
    else
      out += c;
  }
  return out + "'";
}

}  // namespace cs::reports

#include "reports/figures/gnuplot.hpp"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <sys/wait.h>

namespace cs::reports {
namespace {

int exit_status(int system_result) {
  if (system_result == -1)
    return -1;
  if (WIFEXITED(system_result))
    return WEXITSTATUS(system_result);
  return -1;
}

bool offers_terminal(const std::string& program, const std::string& terminal) {
  const std::string command = fmt::format("{} -e {} >/dev/null 2>&1", shell_quote(program),
                                          shell_quote("set terminal " + terminal));
  return exit_status(std::system(command.c_str())) == 0;
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
  const std::string command = fmt::format("{} {} >{} 2>&1", shell_quote(gnuplot.program),
                                          shell_quote(script.string()), shell_quote(log.string()));
  const int status = exit_status(std::system(command.c_str()));
  if (status == 0)
    return {};
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
  std::string pattern = (std::filesystem::temp_directory_path() / "cs-report-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a temporary directory");
  path_ = pattern;
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string gnuplot_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "''";
    else
      out += c;
  }
  return out + "'";
}

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

}  // namespace cs::reports

#pragma once
// Helpers of the end-to-end tests of the contact-suite executable (tests/apps): running it with
// its output captured, temporary directories, reading files.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"

namespace cs::apps::testing {

/// How one run of the executable ended.
struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs contact-suite with `args` (each passed as one shell word), stdout and stderr captured,
/// with `tmpdir` as its TMPDIR; by default a scratch directory of its own, removed afterwards,
/// so that what a run keeps there (a failed case's files) or a killed one leaves stays out of
/// /tmp.
inline CliRun run_cli(const std::vector<std::string>& args,
                      const std::filesystem::path& tmpdir = {}) {
  char err_path[] = "/tmp/contact-suite-cli-test-XXXXXX";
  const int fd = mkstemp(err_path);
  if (fd < 0)
    throw std::runtime_error("mkstemp failed");
  close(fd);
  char scratch[] = "/tmp/contact-suite-cli-tmp-XXXXXX";
  if (tmpdir.empty() && mkdtemp(scratch) == nullptr)
    throw std::runtime_error("mkdtemp failed");
  const std::string tmp = tmpdir.empty() ? std::string(scratch) : tmpdir.string();
  std::string command = "TMPDIR='" + tmp + "' '" + CONTACT_SUITE_EXE + "'";
  for (const std::string& arg : args)
    command += " '" + arg + "'";
  command += std::string(" 2>'") + err_path + "'";

  CliRun result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr)
    throw std::runtime_error("popen failed");
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.err = read_text(err_path);
  std::filesystem::remove(err_path);
  if (tmpdir.empty())
    std::filesystem::remove_all(scratch);
  return result;
}

using cs::testing::TempDir;

}  // namespace cs::apps::testing

// `contact-suite report ... --bench FILE` end to end: the executable writes section 8,
// "Benchmarks", into report.md from Google Benchmark JSON (the hand-written fixture
// tests/reports/data/small_bench.json), and a bench file it cannot use is bad input: exit code
// 2, one line on stderr naming the file, and the output directory left as it was.

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace cs::apps {
namespace {

namespace fs = std::filesystem;

fs::path data_dir() {
  return fs::path(CONTACT_SUITE_SOURCE_DIR) / "tests" / "reports" / "data";
}

using testing::read_text;
using testing::TempDir;

struct ReportRun {
  int exit_code = -1;
  std::string err;
};

/// Runs `contact-suite report` with `args` (each one shell word), stdout discarded.
ReportRun report(const std::vector<std::string>& args, const fs::path& err_file) {
  std::string command = std::string("'") + CONTACT_SUITE_EXE + "' report";
  for (const auto& a : args)
    command += " '" + a + "'";
  command += " >/dev/null 2>'" + err_file.string() + "'";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(err_file)};
}

TEST(ReportBenchCli, WritesTheBenchmarkSection) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  const ReportRun r =
      report({"--results", (data_dir() / "small_results.json").string(), "--out", out.string(),
              "--no-figures", "--bench", (data_dir() / "small_bench.json").string()},
             tmp.path() / "err.txt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_text(out / "report.md").find("[Benchmarks](appendix-benchmarks.md)"),
            std::string::npos);
  const std::string md = read_text(out / "appendix-benchmarks.md");
  EXPECT_NE(md.find("**Machine** (`" + (data_dir() / "small_bench.json").string() +
                    "`): host `bench-host`, 2 CPUs at 2800 MHz"),
            std::string::npos);
  EXPECT_NE(md.find("| H<sub>p</sub>, mesh F, Q4 | ss | AL | 1.60 |"), std::string::npos);
}

TEST(ReportBenchCli, ABadBenchFileExitsWith2AndLeavesTheDirectoryAlone) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  fs::create_directories(out);
  std::ofstream(out / ".contact-suite");  // an earlier report's directory
  std::ofstream(out / "report.md") << "the user's previous report\n";
  const fs::path bad = tmp.path() / "bench.json";
  std::ofstream(bad) << R"({"context": {}, "benchmarks": [{"name": "BM_Other", )";
  for (const fs::path& bench : {bad, tmp.path() / "missing.json"}) {
    const ReportRun r = report({"--results", (data_dir() / "small_results.json").string(), "--out",
                                out.string(), "--bench", bench.string()},
                               tmp.path() / "err.txt");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("contact-suite: error: bench file '" + bench.string() + "'", 0), 0u)
        << r.err;
    EXPECT_EQ(read_text(out / "report.md"), "the user's previous report\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 2);
  }
}

}  // namespace
}  // namespace cs::apps

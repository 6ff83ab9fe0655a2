// Requirement (issue 16): no shell or plot-script injection from names and paths, and no mixed
// outputs: an --out holding a newline is refused before anything is written (the reproducer of
// the issue created a file through gnuplot), and a second run into a directory that a first
// run holds is refused with exit 2 while the first one's results and report stay consistent.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "apps/cli_support.hpp"
#include "platform/child_process.hpp"

namespace cs::apps::testing {
namespace {

namespace fs = std::filesystem;

platform::ChildResult run_args(const fs::path& dir, std::vector<std::string> args) {
  platform::ChildOptions o;
  o.argv = {CONTACT_SUITE_EXE};
  o.argv.insert(o.argv.end(), args.begin(), args.end());
  o.working_directory = dir;
  o.time_limit_seconds = 300;
  return platform::run_child(o);
}

TEST(OutputSafety, ANewlineInTheOutputPathCannotInjectCommands) {
  TempDir tmp;
  ASSERT_EQ(
      run_args(tmp.path(), {"run", "--problems", "P_p", "--meshes", "C", "--elements", "Q4",
                            "--algorithms", "AL", "--contacts", "ss", "--out", "r", "--no-report"})
          .exit_code,
      0);
  const std::string evil = "inj\nsystem \"touch PWNED\"\n#";
  EXPECT_EQ(
      run_args(tmp.path(), {"report", "--results", "r/results.json", "--out", evil}).exit_code, 2);
  EXPECT_EQ(run_args(tmp.path(), {"run", "--problems", "P_p", "--meshes", "C", "--elements", "Q4",
                                  "--algorithms", "AL", "--contacts", "ss", "--out", evil})
                .exit_code,
            2);
  EXPECT_FALSE(fs::exists(tmp.path() / "PWNED"));
  EXPECT_FALSE(fs::exists(tmp.path() / evil));
}

TEST(OutputSafety, ASecondRunIntoABusyDirectoryIsRefusedAndTheFirstStaysWhole) {
  TempDir tmp;
  std::thread first([&] {
    const auto r = run_args(tmp.path(), {"run", "--problems", "H_p", "--meshes", "C,M,F",
                                         "--elements", "Q4", "--out", "D", "--jobs", "1"});
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.describe();
  });
  // Wait until the first run holds D (its lock file appears), then try a second run into it.
  for (int i = 0; i < 600 && !fs::exists(tmp.path() / ".D.lock"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const auto second = run_args(tmp.path(), {"run", "--problems", "P_p", "--meshes", "C",
                                            "--elements", "Q4", "--out", "D", "--jobs", "1"});
  first.join();
  EXPECT_EQ(second.exit_code, 2);
  const std::string results = read_text(tmp.path() / "D" / "results.json");
  const std::string csv = read_text(tmp.path() / "D" / "results.csv");
  EXPECT_NE(results.find("\"H_p\""), std::string::npos);
  EXPECT_EQ(results.find("\"P_p\""), std::string::npos);
  EXPECT_NE(csv.find("H_p/C/Q4"), std::string::npos);
  EXPECT_EQ(csv.find("P_p/C/Q4"), std::string::npos);
}

}  // namespace
}  // namespace cs::apps::testing

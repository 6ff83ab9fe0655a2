// Requirement: run_child runs a program from an argument vector without a shell, honours the
// working directory, environment, redirections and time limit, and reports how the child ended.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "platform/child_process.hpp"
#include "platform/platform_error.hpp"
#include "support/temp_dir.hpp"

namespace cs::platform {
namespace {

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

ChildOptions shell_free(std::vector<std::string> argv) {
  ChildOptions options;
  options.argv = std::move(argv);
  return options;
}

TEST(ChildProcess, ReportsExitCodes) {
  const ChildResult ok = run_child(shell_free({"true"}));
  EXPECT_TRUE(ok.started);
  EXPECT_TRUE(ok.succeeded());
  EXPECT_EQ(ok.exit_code, 0);
  const ChildResult bad = run_child(shell_free({"false"}));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_FALSE(bad.succeeded());
  EXPECT_EQ(bad.describe(), "exited with status 1");
}

TEST(ChildProcess, ReportsTheTerminatingSignal) {
  // A child that dies by a signal of its own (perl sends itself SIGSEGV).
  const ChildResult s = run_child(shell_free({"perl", "-e", "kill 'SEGV', $$"}));
  ASSERT_TRUE(s.started) << s.spawn_error;
  EXPECT_EQ(s.signal, SIGSEGV);
  EXPECT_EQ(s.exit_code, -1);
  EXPECT_FALSE(s.succeeded());
  EXPECT_NE(s.describe().find("signal 11"), std::string::npos) << s.describe();
}

TEST(ChildProcess, TimeLimitStopsTheChildQuickly) {
  ChildOptions options = shell_free({"sleep", "5"});
  options.time_limit_seconds = 0.3;
  const ChildResult r = run_child(options);
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.signal, SIGTERM);
  EXPECT_GE(r.wall_seconds, 0.3);
  EXPECT_LT(r.wall_seconds, 1.5);  // limit + SIGTERM; far from the 5 s the child wanted
  EXPECT_NE(r.describe().find("timed out"), std::string::npos);
}

TEST(ChildProcess, ChildIgnoringTermIsKilledAfterTheGrace) {
  ChildOptions options = shell_free({"perl", "-e", "$SIG{TERM} = 'IGNORE'; sleep 10"});
  options.time_limit_seconds = 0.2;
  options.kill_grace_seconds = 0.2;
  const ChildResult r = run_child(options);
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_LT(r.wall_seconds, 3.0);  // limit + grace + scheduling; not the 10 s
}

TEST(ChildProcess, ArgumentsReachTheChildVerbatim) {
  cs::testing::TempDir dir;
  // Everything a shell would interpret: spaces, both quotes, ';', '$(...)', a backtick, '|',
  // '>', a glob and a newline. With a shell, `touch` would run and the bytes would differ.
  const std::string evil = "a b 'c' \"d\"; touch " + (dir.path() / "PWNED").string() + " $(touch " +
                           (dir.path() / "PWNED2").string() + ") `id` | > * \n#end";
  ChildOptions options = shell_free({"/usr/bin/printf", "%s", evil});
  options.stdout_path = dir.path() / "out.txt";
  const ChildResult r = run_child(options);
  ASSERT_TRUE(r.succeeded()) << r.describe();
  EXPECT_EQ(read_all(dir.path() / "out.txt"), evil);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "PWNED"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "PWNED2"));
}

TEST(ChildProcess, MissingProgramIsAClearError) {
  const ChildResult r = run_child(shell_free({"no-such-program-cs-42"}));
  EXPECT_FALSE(r.started);
  EXPECT_FALSE(r.succeeded());
  EXPECT_EQ(r.spawn_error, "cannot run 'no-such-program-cs-42': program not found in PATH");
  EXPECT_EQ(r.describe(), r.spawn_error);
  const ChildResult p = run_child(shell_free({"/nonexistent/dir/prog"}));
  EXPECT_FALSE(p.started);
  EXPECT_NE(p.spawn_error.find("No such file"), std::string::npos) << p.spawn_error;
}

TEST(ChildProcess, WorkingDirectoryIsHonoured) {
  cs::testing::TempDir dir;
  std::filesystem::create_directory(dir.path() / "work");
  ChildOptions options = shell_free({"pwd"});
  options.working_directory = dir.path() / "work";
  options.stdout_path = dir.path() / "pwd.txt";
  const auto before = std::filesystem::current_path();
  ASSERT_TRUE(run_child(options).succeeded());
  EXPECT_EQ(read_all(dir.path() / "pwd.txt"),
            std::filesystem::canonical(dir.path() / "work").string() + "\n");
  EXPECT_EQ(std::filesystem::current_path(), before);  // ours is untouched
}

TEST(ChildProcess, EnvironmentIsAddedAndReplaced) {
  cs::testing::TempDir dir;
  ChildOptions options = shell_free({"env"});
  options.environment = {{"OMP_NUM_THREADS", "1"}, {"CS_TEST_VALUE", "a b;c"}};
  options.stdout_path = dir.path() / "env.txt";
  ASSERT_TRUE(run_child(options).succeeded());
  const std::string env = read_all(dir.path() / "env.txt");
  EXPECT_NE(env.find("\nOMP_NUM_THREADS=1\n"), std::string::npos);
  EXPECT_NE(env.find("CS_TEST_VALUE=a b;c\n"), std::string::npos);
  EXPECT_NE(env.find("PATH="), std::string::npos);  // ours is inherited
}

TEST(ChildProcess, StdoutAndStderrGoToTheirFiles) {
  cs::testing::TempDir dir;
  ChildOptions options = shell_free({"perl", "-e", "print STDOUT 'out'; print STDERR 'err'"});
  options.stdout_path = dir.path() / "o.txt";
  options.stderr_path = dir.path() / "e.txt";
  ASSERT_TRUE(run_child(options).succeeded());
  EXPECT_EQ(read_all(dir.path() / "o.txt"), "out");
  EXPECT_EQ(read_all(dir.path() / "e.txt"), "err");
  options.stderr_path = options.stdout_path;  // one file for both
  ASSERT_TRUE(run_child(options).succeeded());
  const std::string both = read_all(dir.path() / "o.txt");
  EXPECT_EQ(both.size(), 6u);
  EXPECT_NE(both.find("err"), std::string::npos);
}

TEST(ChildProcess, ChildRunsInItsOwnProcessGroup) {
  cs::testing::TempDir dir;
  ChildOptions options = shell_free({"perl", "-e", "print getpgrp() == $$ ? 'leader' : 'member'"});
  options.stdout_path = dir.path() / "g.txt";
  ASSERT_TRUE(run_child(options).succeeded());
  EXPECT_EQ(read_all(dir.path() / "g.txt"), "leader");
}

TEST(ChildProcess, MeasuresPeakMemory) {
  // perl builds a 50 MB string: the child's peak RSS must show it (ours is irrelevant).
  const ChildResult r = run_child(shell_free({"perl", "-e", "my $s = 'x' x 50000000;"}));
  ASSERT_TRUE(r.succeeded());
  EXPECT_GT(r.peak_rss_mb, 45.0);
  EXPECT_LT(r.peak_rss_mb, 500.0);
  EXPECT_GT(r.wall_seconds, 0.0);
}

// Requirement (issue 25, item 3): a child dies with us. A process that runs a child through
// run_child and is then killed with SIGKILL (no handler can run) takes the child with it, so
// gnuplot or ccx never writes on into an abandoned staging directory.
TEST(ChildProcess, TheChildDiesWhenWeAreKilled) {
  cs::testing::TempDir tmp;
  const std::filesystem::path pid_file = tmp.path() / "child.pid";
  const pid_t runner = fork();
  ASSERT_GE(runner, 0);
  if (runner == 0) {  // the process that will be killed: runs a child for 30 s
    ChildOptions o =
        shell_free({"sh", "-c", "echo $$ > '" + pid_file.string() + "'; exec sleep 30"});
    run_child(o);
    _exit(0);
  }
  pid_t child = 0;
  for (int i = 0; i < 500 && child == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::istringstream(read_all(pid_file)) >> child;
  }
  ASSERT_GT(child, 0) << "the child never started";
  ASSERT_EQ(kill(runner, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(runner, &status, 0), runner);
  // The kernel sends SIGKILL to the child as the runner's thread exits: allow it 2 s (it takes
  // microseconds; the margin is for a loaded machine). The child is init's to reap, so a
  // zombie counts as dead: its /proc state is Z.
  bool dead = false;
  for (int i = 0; i < 200 && !dead; ++i) {
    const std::string stat = read_all("/proc/" + std::to_string(child) + "/stat");
    const auto close = stat.rfind(')');
    dead = stat.empty() || (close != std::string::npos && stat.substr(close + 2, 1) == "Z");
    if (!dead)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!dead)
    kill(child, SIGKILL);
  EXPECT_TRUE(dead) << "the child outlived the killed process";
}

TEST(ChildProcess, BadOptionsThrow) {
  EXPECT_THROW(run_child(ChildOptions{}), PlatformError);
  ChildOptions options = shell_free({"true"});
  options.environment = {{"A=B", "1"}};
  EXPECT_THROW(run_child(options), PlatformError);
  options = shell_free({"true"});
  options.time_limit_seconds = -1.0;
  EXPECT_THROW(run_child(options), PlatformError);
  options = shell_free({"true"});
  options.working_directory = "/nonexistent/dir";
  EXPECT_THROW(run_child(options), PlatformError);
}

}  // namespace
}  // namespace cs::platform

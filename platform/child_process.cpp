#include "platform/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "platform/interrupts.hpp"
#include "platform/platform_error.hpp"

extern char** environ;

namespace cs::platform {
namespace {

using Clock = std::chrono::steady_clock;

void check(const ChildOptions& options) {
  if (options.argv.empty() || options.argv[0].empty())
    throw PlatformError("run_child: no program given (empty argument vector)");
  for (const auto& [name, value] : options.environment) {
    if (name.empty() || name.find('=') != std::string::npos)
      throw PlatformError("run_child: bad environment variable name '" + name + "'");
  }
  if (!(options.time_limit_seconds >= 0.0 && options.time_limit_seconds <= kMaxTimeLimitSeconds))
    throw PlatformError("run_child: time limit must be in [0, " +
                        std::to_string(static_cast<int>(kMaxTimeLimitSeconds)) + "] seconds");
  if (!(options.kill_grace_seconds >= 0.0) || !std::isfinite(options.kill_grace_seconds))
    throw PlatformError("run_child: kill grace period must be >= 0 and finite");
  const auto& dir = options.working_directory;
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw PlatformError("run_child: working directory '" + dir.string() + "' does not exist");
}

/// Our environment with the options' variables added or replaced, as "NAME=value" strings.
std::vector<std::string> child_environment(const ChildOptions& options) {
  std::vector<std::string> env;
  for (char** e = environ; e != nullptr && *e != nullptr; ++e) {
    const std::string entry(*e);
    const auto name = entry.substr(0, entry.find('='));
    const bool replaced = std::any_of(options.environment.begin(), options.environment.end(),
                                      [&](const auto& kv) { return kv.first == name; });
    if (!replaced)
      env.push_back(entry);
  }
  for (const auto& [name, value] : options.environment)
    env.push_back(name + "=" + value);
  return env;
}

/// A null-terminated array of pointers into `strings` (which must outlive it).
std::vector<char*> c_array(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (auto& s : strings)
    out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

std::string output_target(const std::filesystem::path& path) {
  return path.empty() ? std::string("/dev/null") : std::filesystem::absolute(path).string();
}

/// The program's path: argv[0] itself when it holds '/', else the first executable of that name
/// in our PATH (as posix_spawnp and execvp search); empty when there is none.
std::string resolve_program(const std::string& program) {
  if (program.find('/') != std::string::npos)
    return program;
  const char* path = std::getenv("PATH");
  std::string dirs = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
  for (std::size_t at = 0; at <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', at), dirs.size());
    const std::string dir = end > at ? dirs.substr(at, end - at) : ".";
    const std::string candidate = dir + "/" + program;
    if (access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate))
      return candidate;
    at = end + 1;
  }
  return {};
}

/// Everything the child needs, prepared before fork(): between fork() and exec() the child
/// (a copy of a multi-threaded process) may only make async-signal-safe calls.
struct ExecPlan {
  std::string program, out, err, dir;
  char* const* argv;
  char* const* envp;
  pid_t parent;
};

/// Runs in the child: never returns. Reports a failure as its errno on `error_fd` (close-on-
/// exec, so a successful exec closes it and the parent reads nothing).
[[noreturn]] void exec_child(const ExecPlan& plan, int error_fd) {
  auto fail = [error_fd](int error) {
    [[maybe_unused]] const ssize_t n = write(error_fd, &error, sizeof error);
    _exit(127);
  };
  // Killed when the thread that started it dies, SIGKILL included; if the parent died before
  // this line the signal will never come, so leave at once.
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0)
    fail(errno);
  if (getppid() != plan.parent)
    _exit(127);
  setpgid(0, 0);  // a new group whose id is the child's pid
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  for (int sig : {SIGINT, SIGTERM, SIGQUIT, SIGHUP, SIGPIPE})
    sigaction(sig, &dfl, nullptr);
  sigset_t empty;
  sigemptyset(&empty);
  sigprocmask(SIG_SETMASK, &empty, nullptr);
  const int in = open("/dev/null", O_RDONLY);
  const int out = open(plan.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (in < 0 || out < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0)
    fail(errno);
  if (plan.err == plan.out && plan.err != "/dev/null") {
    if (dup2(1, 2) < 0)
      fail(errno);
  } else {
    const int err = open(plan.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err < 0 || dup2(err, 2) < 0)
      fail(errno);
  }
  // No descriptor above 2 survives exec (error_fd is close-on-exec).
  if (error_fd > 3)
    close_range(3, static_cast<unsigned>(error_fd) - 1, 0);
  close_range(static_cast<unsigned>(error_fd) + 1, ~0U, 0);
  if (!plan.dir.empty() && chdir(plan.dir.c_str()) != 0)
    fail(errno);
  execve(plan.program.c_str(), plan.argv, plan.envp);
  fail(errno);
  _exit(127);
}

/// fork() + exec_child; returns the child's pid, or -errno when it could not start.
pid_t start_child(const ExecPlan& plan) {
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0)
    return -errno;
  const pid_t pid = fork();
  if (pid == 0)
    exec_child(plan, pipe_fds[1]);
  const int fork_error = errno;
  close(pipe_fds[1]);
  if (pid < 0) {
    close(pipe_fds[0]);
    return -fork_error;
  }
  setpgid(pid, pid);  // also here, so that the group exists before we may signal it
  int error = 0;
  ssize_t n = 0;
  while ((n = read(pipe_fds[0], &error, sizeof error)) < 0 && errno == EINTR) {
  }
  close(pipe_fds[0]);
  if (n == static_cast<ssize_t>(sizeof error)) {  // exec failed: reap the child
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return -error;
  }
  return pid;
}

std::string spawn_error_message(const ChildOptions& options, int error) {
  const std::string& program = options.argv[0];
  if (error == ENOENT && program.find('/') == std::string::npos)
    return "cannot run '" + program + "': program not found in PATH";
  return "cannot run '" + program + "': " + std::strerror(error);
}

/// True once the child has exited (it stays a zombie: its pid and group id stay reserved).
bool has_exited(pid_t pid) {
  siginfo_t info{};
  const int rc = waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT);
  return rc == 0 ? info.si_pid == pid : errno != EINTR;
}

/// Waits until the child exits or `deadline` passes; false on the deadline or, when
/// `stop_on_interrupt`, on an interrupt.
bool wait_until(pid_t pid, Clock::time_point deadline, bool stop_on_interrupt) {
  auto nap = std::chrono::microseconds(500);
  while (!has_exited(pid)) {
    if (Clock::now() >= deadline || (stop_on_interrupt && interrupted_signal() != 0))
      return false;
    std::this_thread::sleep_for(nap);
    nap = std::min(nap * 2, std::chrono::microseconds(20000));
  }
  return true;
}

/// Sends `first` to the child's group, then SIGKILL after the grace period if it still runs.
void stop_group(pid_t pgid, int first, double grace_seconds) {
  kill(-pgid, first);
  const auto grace = std::chrono::duration<double>(grace_seconds);
  wait_until(pgid, Clock::now() + std::chrono::duration_cast<Clock::duration>(grace), false);
  kill(-pgid, SIGKILL);  // a leader that ignored `first`, or stragglers of its group
}

/// Reaps the child, filling exit code, signal and peak RSS.
void reap(pid_t pid, ChildResult& result) {
  int status = 0;
  struct rusage usage {};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status))
    result.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status))
    result.signal = WTERMSIG(status);
  result.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB
}

/// Waits for the child under the time limit and interrupts; stops its group if needed.
void supervise(pid_t pid, const ChildOptions& options, Clock::time_point start,
               ChildResult& result) {
  const auto limit = std::chrono::duration<double>(options.time_limit_seconds);
  const auto deadline = options.time_limit_seconds > 0.0
                            ? start + std::chrono::duration_cast<Clock::duration>(limit)
                            : Clock::time_point::max();
  const bool exited = interrupted_signal() == 0 && wait_until(pid, deadline, true);
  // The handler may have killed the child before we looked: an interrupt seen now counts.
  const int sig = interrupted_signal();
  result.interrupted = sig != 0;
  result.timed_out = !exited && sig == 0;
  if (!exited || sig != 0)
    stop_group(pid, sig != 0 ? sig : SIGTERM, options.kill_grace_seconds);
}

/// Releases a registry slot on every path out of run_child.
struct SlotGuard {
  int slot;
  ~SlotGuard() {
    if (slot >= 0)
      release_child_group_slot(slot);
  }
};

}  // namespace

ChildResult run_child(const ChildOptions& options) {
  check(options);
  ChildResult result;
  if (interrupted_signal() != 0) {
    result.interrupted = true;
    result.spawn_error =
        "not started: interrupted by signal " + std::to_string(interrupted_signal());
    return result;
  }
  SlotGuard guard{reserve_child_group_slot()};
  if (guard.slot < 0)
    throw PlatformError("run_child: too many children running at once");
  std::vector<std::string> args = options.argv;
  std::vector<std::string> env = child_environment(options);
  std::vector<char*> c_args = c_array(args), c_env = c_array(env);
  const ExecPlan plan{resolve_program(options.argv[0]),
                      output_target(options.stdout_path),
                      output_target(options.stderr_path),
                      options.working_directory.string(),
                      c_args.data(),
                      c_env.data(),
                      getpid()};
  const auto start = Clock::now();
  const pid_t pid = plan.program.empty() ? -ENOENT : start_child(plan);
  if (pid < 0) {
    result.spawn_error = spawn_error_message(options, -pid);
    return result;
  }
  result.started = true;
  set_child_group(guard.slot, pid);
  supervise(pid, options, start, result);
  release_child_group_slot(guard.slot);  // before reaping: the group id is still ours
  guard.slot = -1;
  reap(pid, result);
  result.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

std::string ChildResult::describe() const {
  if (!started)
    return spawn_error;
  if (timed_out) {
    char text[64];
    std::snprintf(text, sizeof text, "timed out (stopped after %.3g s)", wall_seconds);
    return text;
  }
  if (interrupted)
    return "interrupted (child stopped, signal " + std::to_string(signal) + ")";
  if (signal != 0)
    return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
  return "exited with status " + std::to_string(exit_code);
}

}  // namespace cs::platform

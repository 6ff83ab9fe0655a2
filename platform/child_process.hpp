#pragma once
// Running an external program without a shell: fork and exec with an argument vector.
//
// No argument is ever interpreted: spaces, quotes, ';', '$(...)' and newlines reach the child
// verbatim, so no user string can become a command. The child
//   - dies with us: it is started with PR_SET_PDEATHSIG = SIGKILL (checked against the race of
//     our death before the call), so a SIGKILL to contact-suite also stops gnuplot or ccx,
//     which would otherwise write on into an abandoned staging directory. The signal follows
//     the thread that called run_child, which blocks until the child ends;
//   - runs in its own process group (its group id is its pid), with the default disposition
//     of SIGINT, SIGTERM, SIGQUIT, SIGHUP and SIGPIPE and an empty signal mask;
//   - reads stdin from /dev/null and writes stdout and stderr to the given files (truncated;
//     /dev/null when none is given; the same path for both shares one file);
//   - inherits no file descriptor above 2, and our environment plus the given variables;
//   - starts in the given working directory (the parent's own is never changed).
// The call blocks until the child exits. On a time-out, or when SIGINT/SIGTERM arrives after
// install_interrupt_forwarding() (platform/interrupts.hpp), the child's whole process group is
// sent SIGTERM (the interrupt's own signal when interrupted), then SIGKILL after a grace
// period; the call then returns with timed_out or interrupted set.
//
// Thread-safe: any number of threads may run children at once (up to kMaxChildGroups).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace cs::platform {

/// What to run and how.
struct ChildOptions {
  /// argv[0] is the program: a path if it contains '/', else searched in PATH. Must not be empty.
  std::vector<std::string> argv;
  /// The child's working directory; empty: ours. Must exist.
  std::filesystem::path working_directory;
  /// Variables added to (or replacing in) our environment, e.g. {"OMP_NUM_THREADS", "1"}.
  std::vector<std::pair<std::string, std::string>> environment;
  /// Files receiving stdout and stderr (created or truncated); empty: /dev/null. Relative
  /// paths are relative to OUR working directory, not the child's.
  std::filesystem::path stdout_path;
  std::filesystem::path stderr_path;
  /// Wall-clock limit in seconds; 0: none. Must be in [0, kMaxTimeLimitSeconds].
  double time_limit_seconds = 0.0;
  /// Seconds between SIGTERM and SIGKILL when the child must be stopped; >= 0.
  double kill_grace_seconds = 2.0;
};

/// The longest time limit a child may be given: one day. Longer ones are refused, since a
/// deadline far enough out overflows the clock and would stop the child at once.
inline constexpr double kMaxTimeLimitSeconds = 86400.0;

/// How the child ended.
struct ChildResult {
  bool started = false;       ///< false: it never ran (see spawn_error)
  std::string spawn_error;    ///< one line, e.g. "cannot run 'ccx': program not found in PATH"
  int exit_code = -1;         ///< the exit status when it exited normally, else -1
  int signal = 0;             ///< the signal that terminated it, else 0
  bool timed_out = false;     ///< stopped because the time limit passed
  bool interrupted = false;   ///< stopped (or never started) because of SIGINT/SIGTERM to us
  double wall_seconds = 0.0;  ///< from spawn to reaping
  double peak_rss_mb = 0.0;   ///< the child's peak resident set (wait4 rusage), MiB

  /// True when the child ran and exited with status 0.
  bool succeeded() const { return started && signal == 0 && !timed_out && exit_code == 0; }
  /// One line: "exited with status 3", "killed by signal 9 (Killed)", "timed out after 0.3 s",
  /// "interrupted by signal 2", or the spawn error.
  std::string describe() const;
};

/// Runs the child to completion (see the file comment). Throws PlatformError for options that
/// cannot be carried out (empty argv, a bad environment name, a negative limit, a missing
/// working directory, no free registry slot); everything that happens to the child is in the
/// result.
ChildResult run_child(const ChildOptions& options);

}  // namespace cs::platform

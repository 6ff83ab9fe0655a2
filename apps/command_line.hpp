#pragma once
// contact-suite's command line: the subcommands, dispatched; every error from input becomes one
// line on stderr and exit 2 (apps/usage_error.hpp). In the library, so that CLI11's parser is
// compiled once, with the commands that use it, and the program's main() is one call.

namespace cs::apps {

/// Runs the command line `argv` (argc words): sets the machine's settings for the process
/// (suites/start_settings.hpp; may execute the program again, once), parses, runs the
/// subcommand and returns the exit code.
int run_command_line(int argc, char** argv);

}  // namespace cs::apps

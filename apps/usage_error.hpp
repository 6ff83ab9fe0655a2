#pragma once
// The error every subcommand throws for bad input: main() prints its one-line message on
// stderr and exits with code 2 (see apps/main.cpp).

#include <stdexcept>
#include <string>

namespace cs::apps {

/// Bad input from the user (an option, a value, a file): exit code 2, message on one line.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

/// Exit codes of the contact-suite command, shared by every subcommand.
enum ExitCode : int {
  kSuccess = 0,       ///< all went well
  kCasesFailed = 1,   ///< the run completed but some cases failed (or a gate failed)
  kBadInput = 2,      ///< bad input: unknown names, out-of-range values, unreadable files
  kOutputFailed = 3,  ///< the output directory could not be written (e.g. no space left)
};

}  // namespace cs::apps

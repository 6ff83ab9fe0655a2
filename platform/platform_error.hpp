#pragma once
// The typed error of the platform layer: a request that cannot be carried out as given (an empty
// argument vector, an environment variable name with '=', too many concurrent children).
// Failures of the child itself (a missing program, a crash, a time-out) are not errors: they are
// reported in the ChildResult (see platform/child_process.hpp).

#include <stdexcept>
#include <string>

namespace cs::platform {

/// Bad input to the platform layer. The message is one line naming the cause.
class PlatformError : public std::invalid_argument {
 public:
  explicit PlatformError(const std::string& what) : std::invalid_argument(what) {}
};

/// The file system failed while an output directory was written (no space left, an I/O error,
/// a rename refused): not bad input and not a bug. The message is one line naming the file and
/// the cause; main() exits with kOutputFailed (3).
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace cs::platform

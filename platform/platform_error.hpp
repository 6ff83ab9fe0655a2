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

}  // namespace cs::platform

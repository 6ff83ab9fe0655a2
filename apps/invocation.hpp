#pragma once
// The command line the program was started with, recorded in results for reproducibility.

#include <string>

namespace cs::apps {

/// Sets (from main) and returns the command line as typed, arguments separated by spaces.
inline std::string& invocation() {
  static std::string line;
  return line;
}

}  // namespace cs::apps

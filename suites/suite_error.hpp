#pragma once
// The error the suites layer throws for bad input (unknown names, out-of-range parameters,
// unwritable output): the command line turns it into one line on stderr and exit code 2.

#include <stdexcept>
#include <string>

namespace cs::suites {

/// Bad input to the suites layer; the message is one line and names the cause.
class SuiteInputError : public std::invalid_argument {
 public:
  explicit SuiteInputError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace cs::suites

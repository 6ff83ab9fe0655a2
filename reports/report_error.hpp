#pragma once
// The error the reports layer throws for input it cannot use: study data or a bench file that
// cannot be read; an output directory that cannot be written. (A results file that is missing,
// not JSON, of another schema or version, truncated or malformed is schema::SchemaError, thrown
// by its one reader, schema::read_results_file.) It derives from std::invalid_argument, so
// the command line prints its one-line message and exits with code 2 (see apps/main.cpp).

#include <stdexcept>
#include <string>

namespace cs::reports {

/// Bad input to a report (a file or a directory the user named): one line a user can act on.
class ReportError : public std::invalid_argument {
 public:
  explicit ReportError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace cs::reports

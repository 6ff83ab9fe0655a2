#pragma once
// Where the command line gives a problem's exact solution: the `contact-suite oracle`
// subcommand that evaluates it and its key in the reference table (`oracle table --json`).
// One value per problem, in its descriptor; tests/apps/test_oracle_cli.cpp checks every
// descriptor's entry against the command.

#include <string_view>

namespace cs::suites {

/// A problem's entry in `contact-suite oracle`. An aggregate without defaults.
struct OracleEntry {
  /// The subcommand that evaluates the exact solution ("hertz-plane"); "table" when only the
  /// reference table gives it (the patch tests' uniform state); "" when the command line has no
  /// entry for the problem's oracle (it is graded through the library alone).
  std::string_view subcommand;
  /// The problem's key in `oracle table --json` ("hertz_plane"); "" when the table has none.
  std::string_view reference_key;
};

}  // namespace cs::suites

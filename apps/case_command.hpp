#pragma once
// `contact-suite case PROBLEM ...`: one analysis, printed as text or as one JSON object.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `case` subcommand on `app`. Exit code: 0 converged, 1 not converged or
/// failed, 2 bad input.
void add_case_command(CLI::App& app, int& exit_code);

}  // namespace cs::apps

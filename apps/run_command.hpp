#pragma once
// `contact-suite run`: the study's case matrix or a subset, in parallel; writes
// DIR/results.json and the report (report.md, results.csv, figures) atomically.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `run` subcommand on `app`. Exit code: 0 all converged, 1 some cases did not
/// converge or failed, 2 bad input.
void add_run_command(CLI::App& app, int& exit_code);

}  // namespace cs::apps

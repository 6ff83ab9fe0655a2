#pragma once
// `contact-suite merge OUT_DIR RESULTS...`: combines the slices of a sharded run (or results of
// separate runs of one build) into OUT_DIR/results.json and its report.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `merge` subcommand. Exit code: 0 all merged cases converged, 1 some did not,
/// 2 bad input (unreadable files, slices of different runs, overlaps, a missing slice).
void add_merge_command(CLI::App& app, int& exit_code);

}  // namespace cs::apps

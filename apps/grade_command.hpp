#pragma once
// `contact-suite grade --import FILE --solver-name NAME --out DIR`: another code's results in
// the import layout (suites/import_csv.hpp, docs/import-export.md) graded like any run, into
// DIR/results.json and its report, as one output transaction.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `grade` subcommand on `app`. Exit code: 0 graded, 2 bad input (nothing
/// written).
void add_grade_command(CLI::App& app, int& exit_code);

}  // namespace cs::apps

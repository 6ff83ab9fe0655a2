#pragma once
// `contact-suite gate --baseline FILE --results FILE [--update] [--junit FILE] [--summary FILE]`:
// the CI accuracy gate, with its verdict per row as JUnit XML and a Markdown summary if asked.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `gate` subcommand. Exit code: 0 passed (or baseline updated), 1 a check
/// failed (the failing rows are printed), 2 bad input (missing or malformed files, files
/// covering different cases, a --junit or --summary file that cannot be written: refused before
/// anything is read).
void add_gate_command(CLI::App& app, int& exit_code);

}  // namespace cs::apps

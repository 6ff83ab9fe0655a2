#pragma once
// `contact-suite gate --baseline FILE --results FILE [--update]`: the CI accuracy gate.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `gate` subcommand. Exit code: 0 passed (or baseline updated), 1 a check
/// failed (the failing rows are printed), 2 bad input (missing or malformed files, files
/// covering different cases).
void add_gate_command(CLI::App& app, int& exit_code);

}  // namespace cs::apps

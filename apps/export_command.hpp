#pragma once
// `contact-suite export`: the selected cases as documented CSV (and a VTU of each mesh) for any
// other code to rebuild and solve; the layout is docs/import-export.md. Written as one output
// transaction: DIR holds the complete old set or the complete new set.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `export` subcommand on `app`. Exit code: 0 written, 2 bad input.
void add_export_command(CLI::App& app, int& exit_code);

}  // namespace cs::apps

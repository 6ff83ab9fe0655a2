#pragma once
// `contact-suite list`: the problems, their parameters with defaults, and the options.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `list` subcommand on `app`.
void add_list_command(CLI::App& app);

}  // namespace cs::apps

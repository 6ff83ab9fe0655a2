#pragma once
// `contact-suite oracle NAME [options]`: evaluate one exact solution, print one JSON object.

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Registers the `oracle` subcommand and its sub-subcommands on `app`. The handlers print a
/// single JSON object on stdout and throw UsageError for bad input.
void add_oracle_command(CLI::App& app);

}  // namespace cs::apps

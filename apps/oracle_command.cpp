#include "apps/oracle_command.hpp"

namespace cs::apps {

void add_oracle_command(CLI::App& app) {
  auto* oracle = app.add_subcommand("oracle", "Evaluate one exact solution; prints one JSON object");
  oracle->require_subcommand(1);
}

}  // namespace cs::apps

#include "apps/solver_option_mappings.hpp"

#include <fmt/format.h>

#include "adapters/protocol/solver_registry.hpp"
#include "adapters/registered_codes.hpp"
#include "suites/solver_support.hpp"

namespace cs::apps {

std::vector<reports::SolverOptionMapping> solver_option_mappings() {
  std::vector<reports::SolverOptionMapping> out;
  std::vector<adapters::protocol::SolverManifest> codes;
  try {
    codes = adapters::registered_codes(adapters::protocol::solver_directories());
  } catch (const adapters::protocol::ManifestError&) {
    return out;
  }
  for (const auto& code : codes) {
    for (const auto& o : code.options) {
      const auto algorithm = suites::study_algorithm(o.family);
      out.push_back({code.name + ":" + o.label,
                     fmt::format("{} {}", schema::to_string(algorithm), o.discretization),
                     o.description, std::string(adapters::protocol::to_string(o.family))});
    }
  }
  return out;
}

}  // namespace cs::apps

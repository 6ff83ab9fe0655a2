#include "adapters/registered_codes.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "adapters/calculix/calculix_manifest.hpp"
#include "adapters/protocol/solver_registry.hpp"

namespace cs::adapters {

std::vector<protocol::SolverManifest> registered_codes(
    const std::vector<std::filesystem::path>& directories) {
  std::vector<protocol::SolverManifest> out = protocol::discover_solvers(directories);
  out.push_back(calculix::calculix_manifest());  // a manifest.json may not be called calculix
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

std::vector<std::string> registered_code_names(
    const std::vector<std::filesystem::path>& directories) {
  std::vector<std::string> out = protocol::readable_solver_names(directories);
  out.emplace_back(calculix::kCalculixName);
  std::sort(out.begin(), out.end());
  return out;
}

protocol::SolverManifest find_code(std::string_view name,
                                   const std::vector<std::filesystem::path>& directories) {
  const auto all = registered_codes(directories);
  for (const auto& m : all)
    if (m.name == name)
      return m;
  std::string known;
  for (const auto& m : all)
    known += ", " + m.name;
  throw protocol::ManifestError(
      fmt::format("no solver '{}' (builtin{}; add a folder with a manifest.json by --solver-dir "
                  "or CONTACT_SUITE_SOLVER_DIRS)",
                  name, known));
}

}  // namespace cs::adapters

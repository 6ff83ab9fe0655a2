#pragma once
// Every code a case can name besides our own solver: CalculiX, whose manifest is declared in
// C++ beside its adapter (adapters/calculix/calculix_manifest.hpp), and every code registered
// by a manifest.json (adapters/protocol/solver_registry.hpp). `list`, `run --solver` and the
// report's option mapping read this one list; none of them names a code.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "adapters/protocol/solver_manifest.hpp"

namespace cs::adapters {

/// The registered codes under `directories` (protocol::solver_directories()), CalculiX
/// included, sorted by name. Throws protocol::ManifestError for a bad manifest or two codes of
/// one name.
std::vector<protocol::SolverManifest> registered_codes(
    const std::vector<std::filesystem::path>& directories);

/// The names of the registered codes under `directories`, CalculiX's included, sorted; a
/// manifest that cannot be read is passed over (protocol::readable_solver_names).
std::vector<std::string> registered_code_names(
    const std::vector<std::filesystem::path>& directories);

/// The registered code called `name`; throws protocol::ManifestError naming the registered
/// codes when there is none.
protocol::SolverManifest find_code(std::string_view name,
                                   const std::vector<std::filesystem::path>& directories);

}  // namespace cs::adapters

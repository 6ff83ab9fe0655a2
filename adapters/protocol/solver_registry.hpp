#pragma once
// Where external codes are found: every folder holding a manifest.json (solver_manifest.hpp)
// directly under one of the solver directories, which are, in order:
//   1. the project's own adapters: PREFIX/share/contact-suite/adapters next to an installed
//      program PREFIX/bin/contact-suite (where `cmake --install` and the .deb put them), else
//      the source tree's adapters/ (CONTACT_SUITE_ADAPTERS_DIR, fixed when the tool is built);
//   2. each folder of the environment variable CONTACT_SUITE_SOLVER_DIRS (':'-separated);
//   3. each folder given on the command line (--solver-dir).
// A solver directory may also be a code's own folder (it holds manifest.json itself). A new
// code is therefore one folder: nothing in apps/, suites/ or reports/ names it.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "adapters/protocol/solver_manifest.hpp"

namespace cs::adapters::protocol {

/// The solver directories (see the file comment); `extra` comes last.
std::vector<std::filesystem::path> solver_directories(
    const std::vector<std::filesystem::path>& extra = {});

/// Every manifest under `directories`, sorted by name. Throws ManifestError for a bad manifest
/// or two codes of one name.
std::vector<SolverManifest> discover_solvers(const std::vector<std::filesystem::path>& directories);

/// The names of the codes whose manifests under `directories` can be read, sorted; a manifest
/// that cannot be read is passed over (for a check of a name, which must not fail on it).
std::vector<std::string> readable_solver_names(
    const std::vector<std::filesystem::path>& directories);

/// The manifest of the code called `name`; throws ManifestError naming the registered codes
/// when there is none.
SolverManifest find_solver(std::string_view name,
                           const std::vector<std::filesystem::path>& directories);

}  // namespace cs::adapters::protocol

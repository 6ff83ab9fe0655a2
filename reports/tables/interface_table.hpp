#pragma once
// The interface checks of every case (schema/interface_checks.hpp) in one section: per check
// its tolerance, how many cases were checked and failed, and the worst case; then the option
// sets that fail a check, with the meshes on which they fail and their worst value.

#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The section (empty when no case of the results carries interface checks).
std::string interface_section(const ResultsIndex& index);

}  // namespace cs::reports

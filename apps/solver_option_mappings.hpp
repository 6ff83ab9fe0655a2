#pragma once
// The option mappings of the solvers with an adapter, for the report's cross-code section
// (reports/ reads results only and does not know the adapters).

#include <vector>

#include "reports/tables/cross_code_section.hpp"

namespace cs::apps {

/// Every adapter's mapping of the study's options (CalculiX: calculix_option_mapping()).
std::vector<reports::SolverOptionMapping> solver_option_mappings();

}  // namespace cs::apps

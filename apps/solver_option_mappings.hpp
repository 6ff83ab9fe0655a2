#pragma once
// The options of every registered code, for the report's cross-code section (reports/ reads
// results only and does not know the codes): each option's own label and description, from
// its manifest (CalculiX's is its adapter's, adapters/calculix/calculix_manifest.hpp), and the
// study column its rows sit under by family.

#include <vector>

#include "reports/tables/cross_code_section.hpp"

namespace cs::apps {

/// One row per option of every registered code (adapters/registered_codes.hpp), keyed by the
/// solver label its results carry ("calculix:hard-ss"). A bad manifest is left out of the
/// report (`run` and `list` name it), not an error here.
std::vector<reports::SolverOptionMapping> solver_option_mappings();

}  // namespace cs::apps

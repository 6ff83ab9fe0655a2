#pragma once
// Section 7 of the report: the graded nodal stresses recovered two ways, side by side, for the
// runs that asked for both (`contact-suite run --recovery spr,extrapolated`): superconvergent
// patch recovery (our default) and extrapolation with averaging (the nodal stresses commercial
// codes print, hence the study's). The contact pressure of the same analysis is the witness of
// which recovery is right where they disagree.

#include <string>

#include "reports/results_index.hpp"

namespace cs::reports {

/// The section's Markdown; empty when no baseline row has an extrapolated twin.
std::string recovery_section(const ResultsIndex& index);

}  // namespace cs::reports

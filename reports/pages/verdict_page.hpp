#pragma once
// The report's first screen: per situation, the signed fine-mesh error and grade of every option
// family x discretization x element; the tied best options in one statement with the threshold
// that ties them; one advice; the failures with their interface-check evidence; the caveats
// (which solvers, which stress recovery). Prose: templates/verdict_page.mustache.

#include <string>
#include <vector>

#include "reports/facts/situation_verdict.hpp"

namespace cs::reports {

/// The verdict page's Markdown (at most 60 lines for the study's battery).
std::string verdict_page(const ResultsIndex& index, const std::vector<SituationVerdict>& situations);

/// A cell of the verdict matrix: "e −0.28 %", "u +75.1 % ✗", "diverges".
std::string verdict_cell(const OptionCell& cell);

}  // namespace cs::reports

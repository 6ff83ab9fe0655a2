#pragma once
// The report's first screen: per situation, the signed fine-mesh error and grade of every option
// family x discretization x element; the tied best options in one statement with the threshold
// that ties them; one advice; the failures with their interface-check evidence; with other codes,
// their advice in one line each; the caveats (which solver, which stress recovery). Prose:
// templates/verdict_page.mustache.

#include <string>
#include <vector>

#include "reports/facts/situation_verdict.hpp"

namespace cs::reports {

/// The codes other than ours in the results, for the verdict page's note: one advice line each
/// (code_advice_lines) and the appendix that grades them.
struct OtherCodesNote {
  std::vector<std::string> advice;
  std::string appendix_file, appendix_title;
};

/// The verdict page's Markdown (at most 60 lines for the study's battery). Its matrix holds our
/// baseline rows (patch-recovered, the study's settings); other codes get one line each.
std::string verdict_page(const ResultsIndex& index, const std::vector<SituationVerdict>& situations,
                         const OtherCodesNote& others = {});

/// A cell of the verdict matrix: "e −0.28 %", "u +75.1 % ✗", "diverges".
std::string verdict_cell(const OptionCell& cell);

}  // namespace cs::reports

#pragma once
// The summary's findings: sentences generated from the data, never written by hand. Each
// names its numbers, so that changing the results changes the sentence.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/results/study_reference.hpp"

namespace cs::reports {

/// What a finding is about.
enum class FindingTopic {
  best_option,         ///< the best option set of one Table 2 row, by fine-mesh error
  study_agreement,     ///< our Table 2 grades against the study's
  largest_difference,  ///< where our values and the study's ANSYS values differ most
  divergence,          ///< which option sets fail to diverge on the flat punch (Eq. 47)
  mortar_mismatched,   ///< mortar on the mismatched-node patch tests (P')
  recovery,            ///< patch-recovered against extrapolated nodal stresses (section 7)
};

struct Finding {
  FindingTopic topic;
  std::string sentence;  ///< Markdown, one sentence (or two)
};

/// The findings of a results file, in the order above.
std::vector<Finding> generate_findings(const ResultsIndex& index, const StudyReference& study);

}  // namespace cs::reports

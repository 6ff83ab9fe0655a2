#pragma once
// The study's four conclusions from its Table 2, each checked against our results and marked
// reproduced, not reproduced or refined, with the evidence that decides it:
//   1. AL (= PM) with 4Q and ss is good to excellent except on the Steuermann problems with
//      the smaller radii (S(1/3), S(1/7)); nearly as good with 8Q; less good with ns.
//   2. LMP (= PLM) with 4Q is good to excellent except where nodes are not aligned (P′);
//      performance drops off with 8Q.
//   3. IMC (our MPC) is uniformly unsatisfactory.
//   4. On the singular flat punch every option diverges (Eq. 47).
// Rows are the nonsingular rows of the study's problems (those with a table in its appendix)
// for 1-3 and the flat-punch rows for 4; a rule's exceptions are rows graded worse than g.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

enum class ConclusionStatus { reproduced, not_reproduced, refined };

struct ConclusionCheck {
  std::string claim;  ///< the study's words, shortened
  ConclusionStatus status = ConclusionStatus::not_reproduced;
  std::string evidence;  ///< computed, Markdown
};

/// The four checks (a check whose rows are absent is left out).
std::vector<ConclusionCheck> check_study_conclusions(const ResultsIndex& index);

/// The section (empty when no check has rows).
std::string study_conclusions_section(const ResultsIndex& index);

}  // namespace cs::reports

#pragma once
// The study's "further mesh refinement would lead to converging results", judged for one row
// from its fourth mesh VF (h/8, `bash ci/refine.sh`): one rule, used by the claims ledger
// (claims 9 and 10) and the estimates appendix alike.

#include "grading/convergence.hpp"
#include "reports/results/results_index.hpp"

namespace cs::reports {

/// What VF says of one row: grading::further_refinement over M-F-VF (converges, at_resolution,
/// plateau, fails) when the VF case converged and the row is evidence (RowFacts::evidence:
/// converged and credible on F, not the luck of one mesh); else why it is not judged.
enum class VfJudgement {
  converges,
  at_resolution,
  plateau,
  fails,
  not_evidence,
  vf_not_converged,
  no_vf
};

/// The judgement from the row's errors, how its VF case ended, its resolution on M
/// (ResultsIndex::read_resolution_percent, 0 for a value read at a point) and whether it is
/// evidence.
VfJudgement vf_judgement(const schema::RowVerdict& row, MeshState vf, double resolution_on_m,
                         bool evidence = true);

/// The same, with those inputs read from `index`.
VfJudgement vf_judgement(const ResultsIndex& index, const schema::RowVerdict& row);

/// The study's claim about a row: "It is probable that in instances not demarked by c's with
/// satisfactory or better results, further mesh refinement would lead to converging results".
/// It applies to a nonsingular row graded s or better on F (Eq. 46) without the study's c over
/// C-M-F. It holds when VF converges, or settles at the study's resolution; a plateau at a
/// larger error (a bias) and a trend that does not converge fail it; a row that is not
/// evidence, or whose VF case is missing or did not converge, leaves it open and is never
/// counted either way.
enum class RefinementClaim {
  not_applicable,
  holds,
  plateau,
  fails,
  not_evidence,
  vf_not_converged,
  no_vf
};

/// The claim for one row (see vf_judgement for the inputs).
RefinementClaim refinement_claim(const schema::RowVerdict& row, MeshState vf,
                                 double resolution_on_m = 0.0, bool evidence = true);
RefinementClaim refinement_claim(const ResultsIndex& index, const schema::RowVerdict& row);

}  // namespace cs::reports

#pragma once
// The study's "further mesh refinement would lead to converging results", judged for one row
// from its fourth mesh VF (h/8, `bash ci/refine.sh`): one rule and one tally of it, used by the
// claims ledger (claims 9 and 10) and the estimates appendix alike.

#include <array>
#include <vector>

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

/// Whether the study's claim applies to a row: "It is probable that in instances not demarked
/// by c's with satisfactory or better results, further mesh refinement would lead to converging
/// results", so a row graded s or better on F (Eq. 46) without the study's c over C-M-F. Where
/// it applies, it holds when VF converges or settles at the study's resolution; a plateau at a
/// larger error (a bias) and a trend that does not converge fail it; a row that is not evidence,
/// or whose VF case is missing or did not converge, leaves it open and is never counted.
bool refinement_claim_applies(const schema::RowVerdict& row);

/// How many rows took each vf_judgement.
struct VfTally {
  std::array<int, 7> by{};
  int operator[](VfJudgement j) const { return by[static_cast<std::size_t>(j)]; }
  /// Rows whose trend was judged: converges, plateau or fails (at_resolution apart).
  int trends() const;
  /// Rows left open: not evidence, or VF not converged.
  int open() const;
};

/// vf_judgement over `rows`.
VfTally tally_vf(const ResultsIndex& index, const std::vector<const schema::RowVerdict*>& rows);

}  // namespace cs::reports

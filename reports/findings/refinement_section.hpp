#pragma once
// "Error estimates and refinement": the Richardson/GCI estimates of every row with C, M and F
// values (grading/richardson.hpp; rows exact to round-off left out), how often the GCI band
// holds the exact value, and, for rows also run on the fourth mesh VF (h/8, `bash
// ci/refine.sh`), whether the study's "further mesh refinement would lead to converging
// results" holds. Only a VF case that converged counts. Per-row data: estimates_csv(). Words:
// templates/refinement_section.mustache.

#include <optional>
#include <string>
#include <vector>

#include "grading/convergence.hpp"
#include "reports/facts/refinement_claim.hpp"
#include "reports/results/results_index.hpp"

namespace cs::reports {

/// True when every error of the row on C, M and F is below schema::kErrorNoiseFloorPercent: the
/// row is exact to round-off and has no estimate worth showing.
bool at_round_off(const schema::RowVerdict& row);

/// The estimates of one problem's rows (round-off rows left out).
struct EstimateSummary {
  schema::ProblemId problem{};
  int rows = 0;          ///< rows with C, M and F values whose F case converged and is credible
  int not_credible = 0;  ///< rows left out: F not converged or not credible (interface checks)
  int asymptotic = 0;    ///< of them, with an estimate (differences of one sign that shrink)
  int bounded = 0;       ///< of the asymptotic ones with an exact value, GCI band holds it
  int with_exact = 0;
  std::optional<double> median_gci;  ///< percent, over the asymptotic rows
};

/// What VF says of one row.
struct VfRow {
  const schema::RowVerdict* row = nullptr;
  MeshState vf = MeshState::missing;
  std::optional<grading::ConvergenceAssessment> trend_cmf, trend_mfvf;
  bool claim_applies = false;  ///< refinement_claim_applies
  VfJudgement judgement = VfJudgement::no_vf;
};

/// The section's facts.
struct RefinementFacts {
  std::vector<EstimateSummary> problems;
  int round_off = 0;           ///< rows left out: exact to round-off on every mesh
  std::vector<VfRow> vf_rows;  ///< every row with a VF case, in document order
  VfTally claim;               ///< the rows the study's claim applies to
  VfTally mpc;                 ///< the MPC rows with an F value
  /// The median |error| (percent) on F and on VF of the MPC rows whose trend was judged.
  double mpc_median_f = 0.0, mpc_median_vf = 0.0;
  int singular_vf = 0;           ///< singular rows with a converged VF case
  int singular_vf_diverges = 0;  ///< of them, strict divergence over M-F-VF
};
RefinementFacts refinement_facts(const ResultsIndex& index);

/// estimates.csv: one line per row with C, M and F values (round-off rows included, marked):
/// values, F error, order, Richardson limit and its error, GCI, whether its band holds the exact
/// value, and the VF value, status, trend and claim; empty when no row has C, M and F values.
std::string estimates_csv(const ResultsIndex& index);

/// The section's Markdown; empty when no row has C, M and F values.
std::string refinement_section(const ResultsIndex& index);

}  // namespace cs::reports

#pragma once
// "Error estimates and refinement": beside each Table 2′ row (graded on F), the observed order
// p, the Richardson limit and Roache's grid convergence index (safety factor 1.25) from the C,
// M, F values, or why there is none (oscillatory, not shrinking, round-off); and, for the rows
// also run on the fourth mesh VF (h/8, `bash ci/refine.sh`), the convergence verdicts over
// C-M-F and M-F-VF side by side, the answer per row to the study's "further mesh refinement
// would lead to converging results", and whether MPC (the study's IMC) improves with
// refinement. Every sentence is computed from the results file.

#include <optional>
#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The study's claim about a row: "It is probable that in instances not demarked by c's with
/// satisfactory or better results, further mesh refinement would lead to converging results".
/// It applies to a nonsingular row graded s or better on F whose C-M-F sequence is not
/// converging; it holds when the M-F-VF sequence converges, and fails when it does not.
enum class RefinementClaim { not_applicable, holds, fails, no_vf };

/// The claim's answer for one row (no_vf: it applies but the row has no VF value).
RefinementClaim refinement_claim(const schema::RowVerdict& row);

/// Whether the GCI band of the F value contains the exact value:
/// |f_F - exact| / |f_F| * 100 <= GCI. Empty without an estimate or an exact value.
std::optional<bool> gci_bounds_error(const schema::RowVerdict& row, double exact);

/// MPC rows with errors on F and VF: how many, how many have |e_VF| < |e_F|, and the median
/// |error| (percent) on each mesh.
struct MpcRefinement {
  int rows = 0;
  int improved = 0;
  double median_f = 0.0;
  double median_vf = 0.0;
};
MpcRefinement mpc_refinement(const ResultsIndex& index);

/// The section's Markdown; empty when no row has three or more meshes.
std::string refinement_section(const ResultsIndex& index);

}  // namespace cs::reports

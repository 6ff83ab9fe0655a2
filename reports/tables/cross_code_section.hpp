#pragma once
// The comparison of codes (facts/solvers.hpp), present when the results hold cases of more than
// one code; its template states the two bases every code is graded on (common: our patch
// recovery of the code's nodal displacements; own: the code's own nodal stresses). A code is
// compared with ours on the same target and with the study's ANSYS value of the column its
// option's family sits in: per row its signed errors, grade and F interface checks; per code
// the advised option and the cost beside ours; a figure of the advised options' pressures.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reports/figures/plot_model.hpp"
#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// How one of a code's options maps to the study's, as its manifest states it (the report reads
/// results only; apps/ hands the mapping in).
struct SolverOptionMapping {
  std::string solver;        ///< "calculix:hard-ss"
  std::string study_option;  ///< "PM ss": the study's column the option's rows sit in
  std::string target;        ///< what the code runs, e.g. "penalty (HARD, K = 50 E), ..."
  std::string fidelity;      ///< the option's family, e.g. "penalty"
};

/// One option of one code on one problem quantity, element and target, on both bases.
struct CodeRow {
  std::string code;    ///< "getfem"
  std::string option;  ///< "nitsche"; ours: "PM ss"
  schema::TargetKind target = schema::TargetKind::Discretized;
  const schema::RowVerdict* common = nullptr;
  const schema::RowVerdict* own = nullptr;  ///< other codes only
};

/// The rows of (problem, quantity, element) of every code without parameter overrides; ours only
/// on the targets and study columns another code ran: ours first, then by code, target, option.
std::vector<CodeRow> code_rows(const ResultsIndex& index, schema::ProblemId problem,
                               schema::Quantity quantity, schema::Element element);

/// One option of a code over the nonsingular rows with an F value (common basis) that every
/// option of the code has, so that a code's options are counted on the same rows (an option
/// without a contact pressure has no contact half-width row); and over its verdict cells (per
/// situation and element, as the verdict page makes them, from the code's rows on that target).
struct OptionTally {
  std::string code, option;
  schema::TargetKind target = schema::TargetKind::Discretized;
  int rows = 0;
  int e = 0;                ///< evidence and e on F
  int g = 0, s = 0, u = 0;  ///< evidence, by grade
  int not_evidence = 0;     ///< not converged on F, not credible, or luck
  int cells = 0;            ///< its verdict cells (other codes only)
  int best_cells = 0;       ///< those among the code's best there (SituationVerdict::best)
};
std::vector<OptionTally> option_tallies(const ResultsIndex& index);

/// The advised options of `code` (on `target`, when given): its tallies among the code's best in
/// the most verdict cells (ties together; options of one grade are not ranked, as on the verdict
/// page); empty when none is best anywhere.
std::vector<const OptionTally*> advised(const std::vector<OptionTally>& tallies,
                                        const std::string& code,
                                        std::optional<schema::TargetKind> target = std::nullopt);

/// A code's cost beside ours on the models both ran (problem, mesh, element, target): its
/// common-basis cases (one run of the code each) and ours on the same models.
struct CostLine {
  std::string label;  ///< "H<sub>p</sub> F" or "all models"
  int cases = 0, ours_cases = 0, converged = 0;
  /// The other code's time over its converged cases; ours over all of its cases.
  double seconds = 0.0, ours_seconds = 0.0, peak_mb = 0.0, ours_peak_mb = 0.0;
};
struct CodeCost {
  std::string code;
  std::vector<CostLine> lines;  ///< per problem and mesh, in the report's order
  CostLine total{"all models"};
};
std::vector<CodeCost> code_costs(const ResultsIndex& index);

/// Draws each code's advised option's fine-mesh contact pressure against the exact one, for
/// H_p and S(1/3), into `out_root`/figures/cross_code_profiles.png; no Figure without curves.
/// Never throws for a plotting failure (the Figure carries the error).
std::vector<Figure> render_cross_code_figure(const ResultsIndex& index,
                                             const std::filesystem::path& out_root,
                                             const FigureOptions& options = {});

/// One line per code other than ours: its advised options per target, e.g. "**calculix**: use
/// linear-ss (best in 10 of 12 verdict cells)." (templates/code_advice.mustache); the section's
/// advice and the verdict page's note on other codes. Empty, as the section is, for results of one
/// code.
std::vector<std::string> code_advice_lines(const ResultsIndex& index);

/// The whole section (empty when the results hold one code only); its cost tables from
/// `cost_run` (every code on the same models in one run, ci/cost-run.sh) when given, else from
/// the results' own cases.
std::string cross_code_section(const ResultsIndex& index, const schema::StudyReference& study,
                               const std::vector<Figure>& figures,
                               const std::vector<SolverOptionMapping>& mappings,
                               const ResultsIndex* cost_run = nullptr);

}  // namespace cs::reports

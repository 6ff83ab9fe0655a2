#pragma once
// The cross-code comparison, present when the results hold cases of more than one solver. It is
// generic over the solvers in the results (facts/solvers.hpp: ours first, then the others by
// name), whatever their number:
//
// - outcome: per solver, problem and mesh, how many cases ended in each status;
// - Table 2′: the study's Table 2 with the solvers side by side, one table per element, a row per
//   Table 2 row of the results, a column per option set another solver ran; each cell holds every
//   solver's fine-mesh grade ("e, c" as format_grade_cell), a status with its mesh where a solver
//   did not finish the finest mesh ("g (M)*, timeout (F)"), then the study's ANSYS cell;
// - the tally: per solver, the rows of Table 2′ that every solver ran, by fine-mesh grade class
//   (e with c, e, g, s, u, and no grade: a case not converged, timed out or failed);
// - the option mapping each solver's adapter states (handed in by apps/);
// - the figure: contact pressure on the fine mesh, one curve per solver against the exact one,
//   for H_p and S(1/3), per element, on the first option set every solver solved with a profile
//   (else the first another solver ran, its missing curves named);
// - the cost on the same cases: the cases every solver ran (matched by same_case_key), per
//   problem and mesh and in total: each solver's wall time (sum of wall_seconds), peak memory
//   (largest peak_rss_mb) and converged cases, and each solver's ratios to the first (ours);
// - the values per mesh: per problem, each solver's value (signed error) on C, M and F, then
//   the study's ANSYS value on F.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "reports/figures/plot_model.hpp"
#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// How one of the study's contact options maps to another solver's own, as its adapter states
/// it (the report reads results only; apps/ hands the mapping in).
struct SolverOptionMapping {
  std::string solver;        ///< the solver's label in results.json, e.g. "calculix"
  std::string study_option;  ///< "ns", "ss", "mortar", "PM", "AL", "LMP", "PLM", "MPC"
  std::string target;    ///< what the solver is given, e.g. "*CONTACT PAIR, TYPE=NODE TO SURFACE"
  std::string fidelity;  ///< "same", "approximated" or "not supported"
  std::string note;      ///< why, in one line
};

/// A solver's cell of a row (see the header), or "—" without a row.
std::string solver_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row);

/// Table 2′ for `element`, or nullopt when no other solver ran a Table 2 row of it.
std::optional<MarkdownTable> build_cross_code_grade_table(const ResultsIndex& index,
                                                          const schema::StudyReference& study,
                                                          schema::Element element);

/// Per solver, rows by fine-mesh grade class: "e, c", "e", "g", "s", "u", "no grade".
struct GradeTally {
  std::map<std::string, int> by_class;
  int rows = 0;
};
std::map<std::string, GradeTally> cross_code_grade_tally(const ResultsIndex& index,
                                                         const schema::StudyReference& study);

/// One table per problem with rows of another solver, in the report's order; columns "Row",
/// "Exact", "C ours", "C CalculiX", ..., "F ANSYS".
std::vector<std::pair<schema::ProblemId, MarkdownTable>> build_cross_code_appendix(
    const ResultsIndex& index, const schema::StudyReference& study);

/// The cost of every solver on a set of matched cases; vectors in SolverCost::solvers order.
struct CostLine {
  std::string label;  ///< "H<sub>p</sub> F", "all cases" or "cases all converged"
  int cases = 0;
  std::vector<double> seconds, peak_mb;
  std::vector<int> converged;

  /// Solver i's wall time (peak memory) over the first solver's, or nullopt when that is 0.
  std::optional<double> time_ratio(std::size_t i) const;
  std::optional<double> memory_ratio(std::size_t i) const;
};
struct SolverCost {
  std::vector<std::string> solvers;
  std::vector<CostLine> lines;  ///< per problem and mesh, in the report's order
  CostLine total, all_converged;
};

/// The cost on the cases every solver ran; nullopt when there is no such case.
std::optional<SolverCost> solver_cost(const ResultsIndex& index);
MarkdownTable cost_table(const SolverCost& cost);

/// One panel of the figure: a problem and element on the fine mesh, one option set.
struct CrossCodePanel {
  schema::ProblemId problem = schema::ProblemId::H_p;
  schema::Element element = schema::Element::Q4;
  Option option;
  std::vector<PlotSeries> curves;    ///< one per solver with a profile, then the exact one
  std::vector<std::string> missing;  ///< solvers without a profile on F (their case's status)
};
std::vector<CrossCodePanel> cross_code_profile_panels(const ResultsIndex& index);

/// Draws the figure into `out_root`/figures/cross_code_profiles.png; no Figure when there are no
/// panels. Never throws for a plotting failure (the Figure carries the error).
std::vector<Figure> render_cross_code_figure(const ResultsIndex& index,
                                             const std::filesystem::path& out_root,
                                             const FigureOptions& options = {});

/// The whole section (empty when the results hold one solver only).
std::string cross_code_section(const ResultsIndex& index, const schema::StudyReference& study,
                               const std::vector<Figure>& figures,
                               const std::vector<SolverOptionMapping>& mappings);

}  // namespace cs::reports

#pragma once
// The tables of the cross-code section.
//
// Table 2′: the study's Table 2 with the solvers side by side. One table per element; a row
// per Table 2 row of the results (grade_table_rows), a column per option set another solver
// ran (cross_code_options); each cell holds every solver's grade of the row on the finest mesh
// ("e, c" as in Table 2, format_grade_cell) and the study's ANSYS cell, e.g.
// "e, c │ g │ ANSYS e, c". A row a solver did not finish on its finest mesh also shows that
// case's status ("g (M)*, timeout (F)", "not converged (F)", "failed (F)").
//
// The tally counts, per solver, the rows of the table's option sets by their fine-mesh grade:
// e with the convergence flag c, e, g, s, u, and no grade (a case not converged, timed out or
// failed).
//
// The cross-code appendix: one table per problem, a row per quantity, element and option set
// another solver ran, and per mesh (C, M, F) each solver's value with its error, then the
// study's ANSYS value on F. A case that did not finish shows its status instead of a value.
//
// The cost of each solver on the same cases: the cases of the document that our solver and
// another solver both ran (matched by same_case_key: problem, mesh, element, algorithm,
// contact, target and overrides alike), per problem and mesh and over all of them:
//   wall time  the sum of the cases' wall_seconds, and the ratio other / ours;
//   memory     the largest peak_rss_mb of the cases, and the ratio other / ours.
// Every case of a pair counts, whatever its status (a timeout counts with the time it took);
// the totals are also given over the pairs where both solvers converged.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/results/study_reference.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {

/// Per solver, rows by fine-mesh grade: "e, c", "e", "g", "s", "u", "no grade".
struct GradeTally {
  std::map<std::string, int> by_class;
  int rows = 0;
};

/// A solver's cell of a row: format_grade_cell, followed by the status of the finest mesh that
/// did not converge when the grade is of a coarser mesh ("g (M)*, timeout (F)"), or that
/// status alone when the row has no grade.
std::string solver_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row);

/// Table 2′ for `element` (columns "Problem", then option labels such as "PM ss"; each cell
/// the solvers' grades in solvers_in() order, then the study's), or nullopt when no other
/// solver ran a Table 2 row of it.
std::optional<MarkdownTable> build_cross_code_grade_table(const ResultsIndex& index,
                                                          const StudyReference& study,
                                                          schema::Element element);

/// The tally of every solver over the rows of Table 2′ (both elements) that all solvers ran.
std::map<std::string, GradeTally> cross_code_grade_tally(const ResultsIndex& index,
                                                         const StudyReference& study);

/// The class a row counts under in GradeTally.
std::string grade_class(const schema::RowVerdict* row);

/// A solver's cell on one mesh: "1.2734 (+0.05 %)", the value alone for a singular quantity,
/// the case's status ("timeout", "not converged", "failed") without a value, or "—".
std::string solver_value_cell(const ResultsIndex& index, const schema::RowVerdict* row,
                              schema::MeshLevel mesh);

/// One table per problem with rows of another solver, in the report's problem order; columns
/// "Row", "Exact", "C ours", "C CalculiX", ..., "F ANSYS".
std::vector<std::pair<schema::ProblemId, MarkdownTable>> build_cross_code_appendix(
    const ResultsIndex& index, const StudyReference& study);

/// The cost of a set of matched cases.
struct CostLine {
  std::string label;  ///< "H<sub>p</sub> F", or "all cases"
  int pairs = 0;
  double ours_seconds = 0.0, other_seconds = 0.0;
  double ours_peak_mb = 0.0, other_peak_mb = 0.0;
  int other_converged = 0;  ///< pairs where the other solver converged

  /// other / ours, or nullopt when ours is 0.
  std::optional<double> time_ratio() const;
  std::optional<double> memory_ratio() const;
};

/// The comparison of one other solver with ours.
struct CrossCodeCost {
  std::string solver;             ///< the other solver's label
  std::vector<CostLine> lines;    ///< per problem and mesh, in the report's order
  CostLine total;                 ///< every pair
  CostLine total_both_converged;  ///< the pairs where both converged
};

/// The comparison as a table: a row per line, then the two totals.
MarkdownTable cost_table(const CrossCodeCost& cost);

/// One comparison per solver other than ours that shares cases with ours (none: empty).
std::vector<CrossCodeCost> cross_code_cost(const ResultsIndex& index);

}  // namespace cs::reports

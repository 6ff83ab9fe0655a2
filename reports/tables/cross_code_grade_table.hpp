#pragma once
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

}  // namespace cs::reports

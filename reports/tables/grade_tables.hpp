#pragma once
// The equivalents of the study's Tables 2a (4Q) and 2b (8Q): accuracy and convergence per
// problem (H_p twice: contact and horizontal stress) and option set, each cell our grade
// beside the study's ANSYS grade, e.g. "e, c │ ANSYS e, c".
//
// Rows are the problems' quantities that the study's Table 2 grades (their definitions'
// `study_row`), in battery order. Columns follow the study's: one per study column (AL, PM;
// LMP, PLM; MPC, the study's IMC), split by contact type where the study's Table 2 splits it
// (AL, PM (ss) and (ns)), and one per contact type the study did not have (mortar). Within
// each, our option sets are merged into one column only where their results coincide
// (option_classes.hpp); otherwise each gets its own column beside the same study grade. Rows
// and columns with no data are left out (and named in a note); a missing cell inside the
// table is "—".

#include <optional>
#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/results/study_reference.hpp"

namespace cs::reports {

/// One row of the study's Table 2: a problem's quantity with the study's row key.
struct GradeTableRow {
  schema::ProblemId problem = schema::ProblemId::P_p;
  /// The graded quantity; nullopt for a row of the study's Table 2 whose problem is not in the
  /// results (named as absent only).
  std::optional<schema::Quantity> quantity;
  std::string study_row;  ///< "main", or for H_p "contact" / "horizontal" (ansys_grades.csv)
  std::string label_md;   ///< e.g. "H<sub>p</sub> (contact)"
};

/// The rows of Table 2 in battery order: those the results' problems define (quantities with
/// a `study_row`), and those of the study's Table 2 whose problem is not in the results.
std::vector<GradeTableRow> grade_table_rows(const ResultsIndex& index, const StudyReference& study);

/// One built table, cells as text: rows[i][0] is the row label, rows[i][j] is under columns[j].
struct GradeTable {
  schema::Element element = schema::Element::Q4;
  std::string title;  ///< Markdown heading text
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> notes;  ///< legend, coincidence statements, omissions
  int cells_compared = 0;          ///< cells with our grade and the study's
  int cells_same = 0, cells_better = 0, cells_worse = 0;

  /// The cell under `column` in the row labelled `row_label`, or nullopt.
  std::optional<std::string> cell(const std::string& row_label, const std::string& column) const;
  std::string markdown() const;
};

/// Table 2a/2b for one element, or nullopt when no Table 2 row of that element was run.
std::optional<GradeTable> build_grade_table(const ResultsIndex& index, const StudyReference& study,
                                            schema::Element element);

/// Our part of a cell: "e, c", "g", "s (M)*", "u!", "failed" or "—" (row == nullptr).
/// Markers: (M) graded on the medium mesh because F is missing; * not all of C, M, F present,
/// no convergence verdict; ! some mesh did not converge (values are the last iterate).
std::string format_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row);

/// Rank of a grade, best first: e 0, g 1, s 2, u 3.
constexpr int grade_rank(schema::Grade grade) {
  return static_cast<int>(grade);
}

/// The section "Tables 2a and 2b" of the report (empty if neither table has rows).
std::string grade_tables_section(const ResultsIndex& index, const StudyReference& study);

}  // namespace cs::reports

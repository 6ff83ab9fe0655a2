#pragma once
// The equivalents of the study's Tables 2a (4Q) and 2b (8Q): accuracy and convergence per
// problem (H_p twice: contact and horizontal stress) and option set, each cell our grade
// beside the study's ANSYS grade, e.g. "e, c │ ANSYS e, c".
//
// Columns follow the study's: AL, PM (ss); AL, PM (ns); LMP, PLM; MPC (the study's IMC); and
// mortar, which the study did not have. Within each, our option sets are merged into one
// column only where their results coincide (option_classes.hpp); otherwise each gets its own
// column beside the same study grade. Rows and columns with no data are left out (and named
// in a note); a missing cell inside the table is "—".

#include <optional>
#include <string>
#include <vector>

#include "reports/results_index.hpp"
#include "reports/study_reference.hpp"

namespace cs::reports {

/// One built table, cells as text: rows[i][0] is the row label, rows[i][j] is under columns[j].
struct GradeTable {
  std::string element;  ///< Q4 | Q8
  std::string title;    ///< Markdown heading text
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
                                            const std::string& element);

/// Our part of a cell: "e, c", "g", "s (M)*", "u!", "failed" or "—" (row == nullptr).
/// Markers: (M) graded on the medium mesh because F is missing; * not all of C, M, F present,
/// no convergence verdict; ! some mesh did not converge (values are the last iterate).
std::string format_grade_cell(const ResultsIndex& index, const RowRecord* row);

/// Rank of a grade, best first: e 0, g 1, s 2, u 3; 4 for anything else.
int grade_rank(const std::string& grade);

/// The section "Tables 2a and 2b" of the report (empty if neither table has rows).
std::string grade_tables_section(const ResultsIndex& index, const StudyReference& study);

}  // namespace cs::reports

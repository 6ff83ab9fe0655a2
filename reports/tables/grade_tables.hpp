#pragma once
// The equivalents of the study's Tables 2a (4Q) and 2b (8Q): per Table 2 row and option column,
// our grade beside the study's ANSYS grade (the template's legend says how a cell reads). Where
// a cell is compared with ANSYS, which prints extrapolated nodal stresses, our grade is that of
// the row's extrapolated twin, the patch-recovered grade beside it. Columns follow the study's,
// then one per contact type it did not have; our option sets share a column only where their
// results coincide (option_classes.hpp).

#include <optional>
#include <string>
#include <vector>

#include "reports/facts/row_facts.hpp"
#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// The key of one row of the study's Table 2: a problem's quantity and the study's row name.
struct StudyRowKey {
  schema::ProblemId problem = schema::ProblemId::P_p;
  /// The graded quantity; nullopt for a row of the study whose problem is not in the results.
  std::optional<schema::Quantity> quantity;
  std::string study_row;  ///< "main", or for H_p "contact" / "horizontal" (ansys_grades.csv)
  std::string label_md;   ///< e.g. "H<sub>p</sub> (contact)"
};

/// The rows of Table 2 in battery order: those the results' problems define, and those of the
/// study's Table 2 whose problem is not in the results.
std::vector<StudyRowKey> grade_table_rows(const ResultsIndex& index,
                                          const schema::StudyReference& study);

/// Our grades against ANSYS's over the cells that have both.
struct AnsysComparison {
  int compared = 0, same = 0, better = 0, worse = 0;
  /// Cells graded by both whose grade of ours is not evidence (RowFacts::evidence: marked ✗,
  /// ‡, or not converged on F): left out of the counts above.
  int not_evidence = 0;
  std::vector<std::string> worse_cells;  ///< "H<sub>a</sub> LMP ss: +2.76 %"
};

/// How two of our option sets that the study groups compare (option_classes.hpp).
struct PairFacts {
  std::string names;          ///< "AL and PM (ss)"
  bool same_method = false;   ///< they coincide and are one method without friction
  OptionComparison compared;  ///< over the table's rows
};

/// One Table 2′ (one element) and what it shows.
struct GradeTableFacts {
  schema::Element element = schema::Element::Q4;
  std::string study_table;  ///< "2a"
  MarkdownTable table{{}};
  bool extrapolated = false;       ///< some cell has an extrapolated grade
  AnsysComparison as_printed;      ///< extrapolated grade (patch where none) against ANSYS
  AnsysComparison patch;           ///< patch-recovered grade against ANSYS
  int not_credible = 0, luck = 0;  ///< cells so marked
  bool in_study_any = false;
  std::vector<PairFacts> pairs;
  std::vector<std::string> rows_absent, groups_absent;
};

/// Table 2a′/2b′ for one element, or nullopt when no Table 2 row of that element was run.
std::optional<GradeTableFacts> build_grade_table(const ResultsIndex& index,
                                                 const schema::StudyReference& study,
                                                 schema::Element element);

/// A row's grade cell: "e, c", "g", "s (M)*", "u!", "failed" or "—" (row == nullptr).
/// Markers: (M) graded on the medium mesh because F is missing; * not all of C, M, F present;
/// ! some mesh did not converge (values are the last iterate).
std::string format_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row);

/// " (e–u)": the grades of the best and worst readings of a value read between two nodes whose
/// resolution leaves its grade open (RowFacts::read_leaves_grade_open); "" otherwise.
std::string open_read_grades(const RowFacts& f);

/// The marks of a row that is not evidence, wherever its grade is printed: " ✗" when its F case
/// fails an interface check (not credible), " ‡" when its grade is the luck of one mesh.
std::string evidence_marks(const RowFacts& f);

/// format_grade_cell with the row's open_read_grades and evidence_marks.
std::string format_marked_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row);

/// The sentence that explains evidence_marks (templates/evidence_marks.mustache), for the
/// sections whose tables carry them.
std::string evidence_marks_legend();

/// The section "Tables 2a and 2b" of the report (empty if neither table has rows).
std::string grade_tables_section(const ResultsIndex& index, const schema::StudyReference& study);

}  // namespace cs::reports

#pragma once
// The verdict per analyst situation (a contact patch, Hertz, a rounded punch, a flat punch, ...):
// for each option family x contact discretization x element (and each other code's option x
// element, when its rows are given), the worst signed F error over the
// situation's graded quantities and its grade, with what disqualifies it (interface checks that
// fail, a grade that is the luck of one mesh, a fine case that did not converge). The best cells
// are not ranked against each other when they share a grade: their spread is stated beside the
// change one refinement makes to the same rows, the noise a ranking would have to beat.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "reports/facts/row_facts.hpp"

namespace cs::reports {

/// One option family with one contact discretization and one element, over a situation; or one
/// option of another code (`code`, e.g. "calculix linear-ss") with one element.
struct OptionCell {
  std::string code;  ///< empty for ours
  OptionFamily family = OptionFamily::penalty;
  /// Set where the family's members give other results in the situation (AL and PM with
  /// friction): the cell is this algorithm's alone.
  std::optional<schema::Algorithm> algorithm;
  /// Our algorithms with rows in the cell: a family's label names only those that were run
  /// ("LMP" where the results hold no PLM).
  std::set<schema::Algorithm> members;
  schema::ContactKind contact = schema::ContactKind::ss;
  schema::Element element = schema::Element::Q4;
  std::vector<const RowFacts*> rows;                  ///< nonsingular situations
  std::vector<const DivergenceFacts*> singular_rows;  ///< the flat punch
  std::optional<double> worst_error;                  ///< signed, the largest |F error|
  std::optional<schema::Grade> worst_grade;           ///< of worst_error; none if not converged
  /// Reads between nodes whose resolution leaves their grade open (RowFacts::
  /// read_leaves_grade_open), evidence otherwise: not graded as they read, but a read whose best
  /// reading (grading::best_reading_grade) is worse than the cell's grade sets it, and its error
  /// becomes worst_error, printed with its resolution (worst_resolution, points; 0: a point).
  std::vector<const RowFacts*> open_reads;
  double worst_resolution = 0.0;
  std::optional<double> min_error, max_error;  ///< signed range of the F errors
  double largest_m_to_f_change = 0.0;          ///< max |e_F - e_M| over its rows (points)
  int n_not_credible = 0, n_luck = 0, n_not_converged = 0;
  int n_failed = 0;           ///< rows whose F case failed (or timed out): no F value at all
  std::string failed_reason;  ///< the first of those cases' reasons
  int n_missing = 0;          ///< rows with a C case but no F case (not run): no grade
  std::set<schema::ProblemId> problems;  ///< the situation's problems it has rows for
  /// The situation's problems another option was run on but this one was not (GetFEM on the
  /// axisymmetric Hertz problem): the cell covers part of the situation, so it has no grade.
  std::vector<schema::ProblemId> not_run_on;
  std::set<std::string> failed_checks;  ///< the interface checks its F cases fail, by name
  bool evidence = false;                ///< every row is evidence (RowFacts::evidence)
  int n_eq47 = 0, n_strict = 0;         ///< the flat punch: rows passing each divergence verdict
};

/// One situation: its problems' cells and the statements a reader needs.
struct SituationVerdict {
  std::string key;    ///< the situation's name, e.g. "smooth_curved"
  std::string title;  ///< its label, capitalized: "Smooth curved contact (Hertz)"
  bool singular = false;
  std::vector<schema::ProblemId> problems;
  std::vector<OptionCell> cells;        ///< every option set present
  std::vector<const OptionCell*> best;  ///< evidence cells of the best grade (ties)
  /// u, not converged on F, failing an interface check not in `common_failures`, or failing
  /// divergence.
  std::vector<const OptionCell*> avoid;
  /// The interface checks that every cell fails: a cause shared by all options (the model, the
  /// mesh or the exact solution), which makes no cell evidence but is no reason to avoid one.
  std::vector<std::string> common_failures;
  std::optional<schema::Grade> best_grade;
  std::optional<double> best_min, best_max;  ///< signed F error range over `best`
  /// How far apart `best` are in accuracy (points): the spread of their worst |F errors|, the
  /// figure a ranking would rest on (−0.59 % and +0.55 % are 0.04 points apart, not 1.1).
  double best_abs_spread = 0.0;
  /// What a ranking of `best` would have to beat (points): the largest M -> F change over its
  /// rows, and at least the study's printed resolution, 0.01 points.
  double best_noise = 0.0;
  /// Where `best` are not tied: those with the smallest F errors, whose worst |error| exceeds
  /// the smallest by no more than the smallest one's M -> F change (at least 0.01 points), and
  /// those within 0.01 points of one of them (leaders_extended: no cut within the study's
  /// resolution); the others of `best` have the grade with larger F errors.
  std::vector<const OptionCell*> leaders;
  double leaders_max_abs = 0.0;   ///< the largest worst |error| of `leaders` (%)
  double leaders_noise = 0.0;     ///< their bound over the smallest (points)
  bool leaders_extended = false;  ///< a leader lies beyond that bound, within 0.01 of another
};

/// The situations present in the results, in the report's order.
std::vector<SituationVerdict> situation_verdicts(const ResultsIndex& index,
                                                 const std::vector<RowFacts>& rows,
                                                 const std::vector<DivergenceFacts>& singular);
/// The cells point into `rows` and `singular`: temporaries are refused.
std::vector<SituationVerdict> situation_verdicts(const ResultsIndex&, std::vector<RowFacts>&&,
                                                 const std::vector<DivergenceFacts>&) = delete;
std::vector<SituationVerdict> situation_verdicts(const ResultsIndex&, const std::vector<RowFacts>&,
                                                 std::vector<DivergenceFacts>&&) = delete;

/// "AL, PM": the algorithms run, in the vocabulary's order; the family's label without any.
std::string members_label(OptionFamily family, const std::set<schema::Algorithm>& members);

/// A cell's option as a matrix row names it: its members and discretization, "AL, PM ss" ("PM
/// ss" for a cell of one algorithm of its family, or where only PM was run), or another code's
/// option, "calculix linear-ss".
std::string option_label(const OptionCell& cell);

/// A compact list of cells: "AL, PM ss/ns/mortar Q4, ss Q8; LMP, PLM ss Q4; calculix linear-ss
/// Q4/Q8".
std::string cells_label(const std::vector<const OptionCell*>& cells);

}  // namespace cs::reports

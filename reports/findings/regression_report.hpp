#pragma once
// DIR/regression.md: a results file against a baseline results file. Per case (matched by
// id) and quantity: the relative value drift, grade and status changes; per row (the study's
// unit: a case less its mesh): changes of the Table 2 grade and of the converging/diverging
// verdicts; and the cases that are only in one of the two files.

#include <optional>
#include <string>
#include <vector>

#include "schema/results_file.hpp"

namespace cs::reports {

/// One quantity of one case present in both files.
struct QuantityDrift {
  std::string case_id;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  std::optional<double> old_value, new_value;
  std::optional<double> old_error, new_error;  ///< percent, when graded
  /// (new - old) / |old|; nullopt when a value is missing or old is 0 (see absolute).
  std::optional<double> relative{};
  std::optional<double> absolute{};  ///< new - old, when both present
  schema::Grade old_grade = schema::Grade::u, new_grade = schema::Grade::u;
  schema::CaseStatus old_status = schema::CaseStatus::failed;
  schema::CaseStatus new_status = schema::CaseStatus::failed;
  /// The grade changed while the value moved by round-off across a band's bound
  /// (grading::grade_change_is_round_off, with the gate's default tolerance): neither worse nor
  /// better.
  bool grade_at_edge() const;
  bool grade_worse() const;   ///< a worse grade, not at a band's edge
  bool grade_better() const;  ///< a better grade, not at a band's edge
};

/// One row present in both files whose verdicts changed.
struct RowVerdictChange {
  std::string row_id;
  std::optional<schema::Grade> old_grade, new_grade;
  std::optional<bool> old_converging, new_converging;
  std::optional<bool> old_diverging, new_diverging;
  bool grade_at_edge = false;  ///< the grade changed by round-off (see QuantityDrift)
  bool worse() const;          ///< grade worse (not at a band's edge), or converging/diverging lost
  bool better() const;         ///< grade better, not at a band's edge
};

/// The comparison of two results files.
struct Regression {
  std::string old_source, new_source;
  std::vector<QuantityDrift> quantities;      ///< every common case-quantity, file order of new
  std::vector<RowVerdictChange> row_changes;  ///< only rows whose verdicts changed
  std::vector<std::string> only_in_new, only_in_old;  ///< case ids
  std::vector<std::string> quantities_only_in_one;    ///< "case: quantity (old|new only)"
  int grades_worse = 0, grades_better = 0, grades_at_edge = 0, status_changes = 0;
};

/// Compares `current` against `baseline`.
Regression compare_results(const schema::ResultsDocument& baseline,
                           const schema::ResultsDocument& current);

/// The Markdown of regression.md.
std::string regression_markdown(const Regression& regression);

}  // namespace cs::reports

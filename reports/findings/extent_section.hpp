#pragma once
// The domain-extent study (`--set extent=K`): how much of an error comes from the study's finite
// block and how much from the discretization, the extent at which a block stands for a
// half-space, the grades at that extent ("S, half-space") beside the study geometry's, and,
// where the results hold them, the same cases with the half-space theory's gap
// (`half_space_gap=1`). Words: templates/extent_section.mustache.

#include <optional>
#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// Relative change of a fine-mesh peak below which the block counts as a half-space (0.05 %).
inline constexpr double kHalfSpaceChangePercent = 0.05;

/// True for a row of the extent study: ours, discretized target, patch recovery, and `extent`
/// its only override, or `extent` with `half_space_gap=1` (such rows are shown here, not among
/// the other variants).
bool in_extent_study(const schema::CaseSpec& spec);

/// How the F error of one option at the study's extent (1) splits, in signed percent of the
/// exact value: the block (Richardson limit at 1 against the limit at the widest extent), the
/// discretization (F against the limit at 1), and what is left at the widest extent.
struct ErrorSplit {
  std::string option;  ///< "σ̄c Q8 LMP ss"
  double f_error = 0.0, block = 0.0, discretization = 0.0, remaining = 0.0;
  double widest = 1.0;
};

/// The extent study of one problem.
struct ExtentFacts {
  schema::ProblemId problem{};
  std::vector<ErrorSplit> splits;  ///< nonsingular problems only
  /// The smallest extent from which on no fine-mesh value changes by kHalfSpaceChangePercent
  /// or more between consecutive extents, and the largest such change from it on (percent).
  std::optional<double> half_space, change_after_half_space;
  /// The series (option set and quantity) with two or more extents at or beyond half_space:
  /// those the statement rests on, of `n_series`.
  int half_space_series = 0, n_series = 0;
  /// Where no extent qualifies: the two widest extents and the change between them (percent).
  std::optional<double> second_widest, widest, last_change;
  /// The extent of the "half-space" grades: of those at or beyond the half-space extent, the
  /// widest with the most options.
  std::optional<double> grades_extent;
  /// The widest extent with rows both ways (target's normal, block's normal).
  std::optional<double> gap_extent;
};

/// Per problem with extent rows, in the report's problem order.
std::vector<ExtentFacts> extent_facts(const ResultsIndex& index);

/// The section (empty when the results hold no row whose only override is `extent`).
std::string extent_section(const ResultsIndex& index);

}  // namespace cs::reports

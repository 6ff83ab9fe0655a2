#pragma once
// Section 7 of the report: the graded nodal stresses recovered two ways, side by side, for the
// runs that asked for both (`contact-suite run --recovery spr,extrapolated`): superconvergent
// patch recovery (our default) and extrapolation with averaging (the nodal stresses commercial
// codes print, hence the study's). Both come from one displacement solution, so where they
// disagree the exact value tells which is right.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The rows of one element graded both ways (on the same mesh), compared where the recovery
/// matters and the row is evidence.
struct RecoveryComparison {
  schema::Element element = schema::Element::Q4;
  /// Rows whose two errors differ by more than schema::kErrorNoiseFloorPercent, evidence on F
  /// (RowFacts::evidence).
  int compared = 0;
  int unaffected = 0;    ///< rows read alike both ways (to round-off): a patch test, or a quantity
                         ///< not recovered from nodal stresses
  int not_evidence = 0;  ///< rows whose values differ but that are not evidence: left out
  int better = 0;        ///< grade better with patch recovery
  int worse = 0;         ///< grade worse with patch recovery
  /// |error| smaller (larger) with patch recovery by more than the study's resolution
  /// (grading::kErrorResolutionPercent); the rest are ties.
  int closer = 0, farther = 0;
  double median_spr = 0.0, median_extrapolated = 0.0;  ///< median |error|, percent
};

/// Per element (Q4, Q8) with at least one row graded both ways.
std::vector<RecoveryComparison> compare_recoveries(const ResultsIndex& index);

/// The section's Markdown; one line saying how to get it when no baseline row has an
/// extrapolated twin. Words: templates/recovery_section.mustache.
std::string recovery_section(const ResultsIndex& index);

}  // namespace cs::reports

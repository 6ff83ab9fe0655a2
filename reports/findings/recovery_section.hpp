#pragma once
// Section 7 of the report: the graded nodal stresses recovered two ways, side by side, for the
// runs that asked for both (`contact-suite run --recovery spr,extrapolated`): superconvergent
// patch recovery (our default) and extrapolation with averaging (the nodal stresses commercial
// codes print, hence the study's). The contact pressure of the same analysis is the witness of
// which recovery is right where they disagree.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The option sets of one element graded both ways (on the same mesh), compared.
struct RecoveryComparison {
  schema::Element element = schema::Element::Q4;
  int compared = 0;                                    ///< option sets graded both ways
  int better = 0;                                      ///< grade better with patch recovery
  int worse = 0;                                       ///< grade worse with patch recovery
  double median_spr = 0.0, median_extrapolated = 0.0;  ///< median |error|, percent
  /// Of the option sets whose grade differs and have a contact pressure: how many, and in how
  /// many the patch-recovered value is the closer of the two to the contact pressure.
  int differing_with_pressure = 0, spr_closer_to_pressure = 0;
};

/// Per element (Q4, Q8) with at least one option set graded both ways.
std::vector<RecoveryComparison> compare_recoveries(const ResultsIndex& index);

/// The section's Markdown; one line saying how to get it when no baseline row has an
/// extrapolated twin. Words: templates/recovery_section.mustache.
std::string recovery_section(const ResultsIndex& index);

}  // namespace cs::reports

#pragma once
// The domain-extent study: how much of an error comes from the study's finite block and how
// much from the discretization, the extent at which a block stands for a half-space, and the
// Steuermann grades at that extent ("S, half-space") beside the study geometry's; and, where the
// results hold them, the same cases with the half-space theory's gap (`half_space_gap=1`).

#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// Relative change of a fine-mesh peak below which the block counts as a half-space (0.05 %).
inline constexpr double kHalfSpaceChangePercent = 0.05;

/// True for a row of the extent study: ours, discretized target, patch recovery, and `extent`
/// its only override, or `extent` with `half_space_gap=1` (such rows are shown here, not among
/// the other variants).
bool in_extent_study(const schema::CaseSpec& spec);

/// The section (empty when the results hold no row whose only override is `extent`).
std::string extent_section(const ResultsIndex& index);

}  // namespace cs::reports

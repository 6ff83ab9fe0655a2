#pragma once
// The report's parameter-sweep section (`run --sweep KEY=V1,V2,...`), shown only when the
// results document holds swept cases: per swept key a table of the error (%), grade and
// iterations of each option set at each value, its figure (figures/sweep_figure.hpp), and plain
// answers computed from the numbers:
//  - fkn: the FKN window where AL/PM reach e (and e or g, and c where C, M and F were run), AL
//    iterations against FKN, whether AL and PM separate, whether any FKN reproduces the study's
//    AL error on S(1/3), and the range a default FKN can take (smallest FKN at which every
//    swept AL/PM row is e or g, largest before a case fails to converge);
//  - ftoln: the largest change FTOLN makes;
//  - pinball: what it does to MPC (error range, cases not converged);
//  - E_ratio: from which ratio the error stops changing (within kSettledPoints);
//  - p_over_E: the spread of the normalized errors (linearity in the load);
//  - any other key: the spread of the errors.

#include <string>

#include "reports/figures/figures.hpp"
#include "reports/results/results_index.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// Two errors closer than this (percentage points) are "the same" in the plain answers.
inline constexpr double kSamePoints = 0.01;
/// The E ratio "stops mattering" once every larger ratio is within this (percentage points)
/// of the error at the largest ratio swept.
inline constexpr double kSettledPoints = 0.05;

/// The section ("## Parameter sweeps ..."), or an empty string when nothing was swept.
/// `figures`: those of render_sweep_figures (linked when drawn).
std::string sweep_section(const ResultsIndex& index, const schema::StudyReference& study,
                          const FigureSet& figures);

}  // namespace cs::reports

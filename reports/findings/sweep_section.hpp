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
// The swept cases are series of the one model (findings/parameter_series.hpp).

#include <string>
#include <vector>

#include "reports/figures/plot_model.hpp"
#include "reports/findings/parameter_series.hpp"
#include "reports/results/results_index.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// Two errors closer than this (percentage points) are "the same" in the plain answers.
inline constexpr double kSamePoints = 0.01;
/// The E ratio "stops mattering" once every larger ratio is within this (percentage points)
/// of the error at the largest ratio swept.
inline constexpr double kSettledPoints = 0.05;

/// The swept keys: those of run.sweep in their order, then any other key with two or more
/// override values among the cases (the extent study's left out), alphabetically.
std::vector<std::string> swept_keys(const schema::ResultsDocument& doc);

/// The series of one key: the cases that differ only in its value, one series per quantity of
/// the case with the smallest value, option sets in document order of their first case. Cases
/// without the key are left out; a series of a single point is kept (still a swept case).
std::vector<ParameterSeries> sweep_series(const schema::ResultsDocument& doc,
                                          const std::string& key);

/// True when no series of the same problem and element has a finer mesh: the mesh the study
/// grades, and the one the section's tables, figures and windows show.
bool on_finest_mesh(const ParameterSeries& series, const std::vector<ParameterSeries>& all);

/// The section ("## Parameter sweeps ..."), or an empty string when nothing was swept.
/// `figures`: those of render_sweep_figures (linked when drawn).
std::string sweep_section(const ResultsIndex& index, const schema::StudyReference& study,
                          const FigureSet& figures);

}  // namespace cs::reports

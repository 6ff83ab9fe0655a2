#pragma once
// The report's parameter-sweep section (`run --sweep KEY=V1,V2,...`), shown only when the
// results document holds swept cases: per swept key a table of the error (%), grade and
// iterations of each option set at each value, its figure (figures/sweep_figure.hpp), and the
// answers its kind asks for (fkn: the FKN window of e and g and a default; pinball: MPC's errors;
// E_ratio: where the error settles; any other key: the spread of the errors), computed from the
// numbers. Words: templates/sweep_section.mustache.

#include <string>
#include <vector>

#include "reports/figures/plot_model.hpp"
#include "reports/findings/parameter_series.hpp"
#include "reports/results/results_index.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// Two errors closer than this (percentage points) are "the same" in the plain answers.
inline constexpr double kSamePoints = 0.01;

/// The keys the document's runs swept: run.sweep's, then those of the runs combined with it.
std::vector<std::string> run_sweep_keys(const schema::ResultsDocument& doc);

/// run_sweep_keys, then any other key with two or more override values among the cases (the
/// extent study's left out), alphabetically.
std::vector<std::string> swept_keys(const schema::ResultsDocument& doc);

/// The series of one key: the cases that differ only in its value, one series per quantity of
/// the case with the smallest value, option sets in document order of their first case. Cases
/// without the key are left out; a series of a single point is kept (still a swept case).
std::vector<ParameterSeries> sweep_series(const schema::ResultsDocument& doc,
                                          const std::string& key);

/// True for a series the answers and figures show: a stress quantity (the contact half-width
/// moves by whole nodes: graded apart) on the finest mesh of its problem and element swept.
bool shown_in_answers(const ParameterSeries& series, const std::vector<ParameterSeries>& all);

/// The section ("## Parameter sweeps ..."), or an empty string when nothing was swept.
/// `figures`: those of render_sweep_figures (linked when drawn).
std::string sweep_section(const ResultsIndex& index, const schema::StudyReference& study,
                          const FigureSet& figures);

}  // namespace cs::reports

#pragma once
// The report's cross-code section, present when the results hold cases of more than one
// solver: the outcome of each solver's cases per problem and mesh, the grade tally, Table 2′
// (grades side by side with the study's ANSYS), the option mapping, the pressure figure, the
// cost on the same cases, and the appendix of values per mesh and solver.

#include <string>
#include <vector>

#include "reports/figures/figures.hpp"
#include "reports/results/results_index.hpp"
#include "reports/results/study_reference.hpp"
#include "reports/tables/solver_option_mapping.hpp"

namespace cs::reports {

/// Per solver, problem and mesh: how many cases ended in each status.
std::string cross_code_outcome_markdown(const ResultsIndex& index);

/// The whole section (empty when the results hold one solver only). `figures` are the cross-code
/// figures (render_cross_code_figure), `mappings` the option mappings of the solvers.
std::string cross_code_section(const ResultsIndex& index, const StudyReference& study,
                               const std::vector<Figure>& figures,
                               const std::vector<SolverOptionMapping>& mappings);

}  // namespace cs::reports

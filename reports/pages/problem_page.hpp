#pragma once
// One page per problem (problem-<id>.md): what it is, its exact values and their source, a
// table per quantity and element (value and signed error on each mesh, grade, the study's c, the
// noise-aware trend, the observed order, credibility), its figures (mesh, profile with C, M, F,
// convergence). AL/PM and LMP/PLM share a row where their values coincide, and say so.
// Prose: templates/problem_page.mustache.

#include <string>
#include <vector>

#include "reports/facts/row_facts.hpp"
#include "reports/figures/figures.hpp"

namespace cs::reports {

/// The file of a problem's page, relative to the report directory: "problem-H_p.md".
std::string problem_page_file(schema::ProblemId problem);

/// The page of one problem; `figures` are every figure of the report (paths relative to it).
std::string problem_page(const ResultsIndex& index, const schema::ProblemRecord& problem,
                         const std::vector<RowFacts>& rows,
                         const std::vector<DivergenceFacts>& singular,
                         const std::vector<const Figure*>& figures);

}  // namespace cs::reports

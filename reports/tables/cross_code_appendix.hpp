#pragma once
// The cross-code appendix: one table per problem, a row per quantity, element and option set
// another solver ran, and per mesh (C, M, F) each solver's value with its error, then the
// study's ANSYS value on F. A case that did not finish shows its status instead of a value.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/results/study_reference.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {

/// A solver's cell on one mesh: "1.2734 (+0.05 %)", the value alone for a singular quantity,
/// the case's status ("timeout", "not converged", "failed") without a value, or "—".
std::string solver_value_cell(const ResultsIndex& index, const schema::RowVerdict* row,
                              schema::MeshLevel mesh);

/// One table per problem with rows of another solver, in the report's problem order; columns
/// "Row", "Exact", "C ours", "C CalculiX", ..., "F ANSYS".
std::vector<std::pair<schema::ProblemId, MarkdownTable>> build_cross_code_appendix(
    const ResultsIndex& index, const StudyReference& study);

}  // namespace cs::reports

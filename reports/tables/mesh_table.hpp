#pragma once
// Table 1′: the elements of the indented body per problem and mesh level, ours (from the
// cases in the results) beside the study's Table 1, with the relative difference where they
// differ, and our element size at the contact h/a (b for S) on each level.

#include <string>

#include "reports/results/results_index.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// The section (empty when the results hold no case).
std::string mesh_table_section(const ResultsIndex& index, const schema::StudyReference& study);

}  // namespace cs::reports

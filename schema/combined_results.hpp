#pragma once
// Several results files read as one document, for a report that draws on more than one run
// (the main job, a sweep, another solver's battery, a refinement run).

#include <string>
#include <vector>

#include "schema/results_file.hpp"

namespace cs::schema {

/// Combines documents into one. The first document's run is the run of the result; the
/// others' are kept, with their sources, in `added_runs` order. Problems are united in battery
/// order (the first record of a problem is kept); cases and rows are concatenated in the order
/// given. A case or row id found in two documents is a SchemaError that names the id and both
/// sources, since the report could not tell which to show. An empty list is a SchemaError.
ResultsDocument combine_results(std::vector<ResultsDocument> documents);

}  // namespace cs::schema

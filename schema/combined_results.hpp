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
/// given. A case or row id found in two documents must be the same analysis run twice (as a
/// refinement run repeats the main job's C, M and F cases beside its VF ones): the same status
/// and values to 1e-9 relative; the first is kept, and a row takes the other's refinement record
/// (M-F-VF) when it has none. With other values it is a SchemaError that names the id and both
/// sources, since the report could not tell which to show. An empty list, or one file (source)
/// given twice, is a SchemaError.
ResultsDocument combine_results(std::vector<ResultsDocument> documents);

}  // namespace cs::schema

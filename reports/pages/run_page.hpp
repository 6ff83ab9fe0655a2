#pragma once
// What the results are: one line for report.md (cases, statuses, files, machine time of the whole
// set) and the run appendix (each results file of the set with its start, wall time, workers,
// peak memory and command; the environment of the first: machine, versions, settings).
// Prose: templates/run_line.mustache, templates/run_page.mustache.

#include <string>

#include "schema/results_file.hpp"

namespace cs::reports {

std::string run_line(const schema::ResultsDocument& doc);

std::string run_page(const schema::ResultsDocument& doc);

}  // namespace cs::reports

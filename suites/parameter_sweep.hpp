#pragma once
// Parameter sweeps (`run --sweep KEY=V1,V2,...`, repeatable): each axis is a `--set` key with a
// list of values; the run's cases are the selection's cases times the cross product of the
// axes, each swept value becoming the case's override (its id, its results.json record).
// Parsed and validated here, once, before anything runs.

#include <map>
#include <string>
#include <vector>

#include "schema/results_file.hpp"
#include "suites/case_spec.hpp"

namespace cs::suites {

using schema::SweepAxis;

/// Parses every `--sweep KEY=V1,V2,...` argument (values as `--set` reads them: a number or a
/// ratio). Throws SuiteInputError with one line for a missing '=' or key, an empty value list,
/// an empty item (two commas), a value that is not a finite number, a value given twice in one
/// list, or a key swept twice.
std::vector<SweepAxis> parse_sweeps(const std::vector<std::string>& texts);

/// Checks the sweep against the selection before anything runs: no key both swept and `--set`,
/// and for every problem selected, the key is one of its parameters and every value is within
/// its range. Throws SuiteInputError naming the key, the value and the problem.
void validate_sweeps(const std::vector<SweepAxis>& sweeps,
                     const std::map<std::string, double>& overrides,
                     const std::vector<ProblemId>& problems);

/// The cross product of the axes, as override maps (the first axis varies slowest); one empty
/// map when there is no axis.
std::vector<std::map<std::string, double>> sweep_points(const std::vector<SweepAxis>& sweeps);

}  // namespace cs::suites

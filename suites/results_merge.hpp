#pragma once
// Merging results files: the slices of a sharded run (`run --shard K/N`, e.g. a Slurm job array)
// or the results of separate runs of one build into one results document, as if one run had
// produced it: cases in the battery's order, rows and problem records recomputed.
//
// Refused, with a one-line SuiteInputError that names the cause:
//   - files of different builds (contact_suite_version differs), unless asked to record them
//     (BuildMix::record, `merge --mixed-builds`: a battery that ran for days across commits
//     that left its cases alone); the merged run's contact_suite_version then names every
//     build and how many files came from it;
//   - slices of different runs (run keys or slice counts differ), or slices mixed with unsharded
//     results;
//   - a slice given twice (overlap) or a slice missing (named: "slice 3/4 is missing");
//   - a case present in two files (named).

#include <string>
#include <vector>

#include "schema/results_file.hpp"

namespace cs::suites {

/// What merge does with files of different builds.
enum class BuildMix { refuse, record };

/// Merges `parts` (at least one). `command_line` is recorded as the merged run's.
schema::ResultsDocument merge_results(const std::vector<schema::ResultsDocument>& parts,
                                      const std::string& command_line,
                                      BuildMix builds = BuildMix::refuse);

/// Sorts cases into the battery's order: problem, mesh, element, algorithm, contact,
/// recovery, then target, solver and overrides (the order of `run` without --shard).
void sort_cases(std::vector<schema::CaseResult>& cases);

}  // namespace cs::suites

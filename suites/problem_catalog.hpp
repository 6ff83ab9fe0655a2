#pragma once
// The catalogue of problems, built from their descriptors: read by `contact-suite list`, the
// case matrix, the case validation, the builders, the mesh generator, the scheduler and the
// results file's `problems` records.
//
// It is a registry with two parts:
//   - the built-in problems, one per enumerator of schema::ProblemId, collected at compile time
//     from their descriptor files (suites/problems/); a missing descriptor fails to link;
//   - problems registered at run time by register_problem (a test's, an extension's): one line,
//     `register_problem("U_p", descriptor)`, gives the problem an id from
//     schema::kFirstRegisteredProblem up and its name, and from then on it runs, grades and is
//     written to results.json like a built-in one.
// Why ProblemId stays an enum rather than becoming a string key: every layer (case ids, the
// gate, results.json, the report) keys on it, and the enumerators let -Werror=switch check the
// few switches that remain over built-in problems in the vocabulary. A reserved id range keeps
// all of that and still admits new problems without an edit outside their own files.

#include <string_view>

#include <map>
#include <string>
#include <vector>

#include "suites/case_result.hpp"
#include "suites/problem_descriptor.hpp"

namespace cs::suites {

/// The descriptor of `id`. Throws SuiteInputError for an id that is neither an enumerator nor
/// registered.
const ProblemDescriptor& problem_descriptor(ProblemId id);

/// True when `id` is a built-in problem or a registered one.
bool is_known_problem(ProblemId id);

/// Registers a problem defined outside the battery under `name` (its name on the command line,
/// in case ids and results.json; see schema::register_problem_name for the rules) and returns
/// its id; the descriptor's record takes that id. Register before running any case of it.
/// Throws schema::SchemaError for a name that is taken or not plain.
ProblemId register_problem(std::string_view name, ProblemDescriptor descriptor);

/// Every problem: the built-in ones in battery order, then the registered ones.
std::vector<ProblemId> all_problems();

/// True for the axisymmetric problems.
bool is_axisymmetric(ProblemId id);
/// True for the singular problems (flat punches): graded for divergence, not accuracy.
bool is_singular(ProblemId id);

/// The study's problems (those with a study table), in battery order: the default of the case
/// matrix. The problems beyond the study (e.g. FP_p) run when asked for by name.
std::vector<ProblemId> study_problems();

/// True for the problems with Coulomb friction (they declare the parameter `mu`).
bool is_frictional(ProblemId id);

/// The schema records of the problems that have a case in `cases`, in battery order.
std::vector<schema::ProblemRecord> problem_records(const std::vector<CaseResult>& cases);

/// Fills in the facts a record read from an older results file lacks (situation, length
/// scale) from the catalogue, for the problems it knows; other records are left as they are.
void refresh_problem_records(std::vector<schema::ProblemRecord>& records);

/// The default value of every settable parameter of the problems that have a case in `cases`.
std::map<ProblemId, std::map<std::string, double>> parameter_defaults(
    const std::vector<CaseResult>& cases);

}  // namespace cs::suites

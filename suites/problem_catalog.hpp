#pragma once
// The catalogue of the battery's problems, built from their descriptors (one file each under
// suites/problems/): read by `contact-suite list`, the case matrix, the case validation, the
// builders and the results file's `problems` records.

#include <map>
#include <string>
#include <vector>

#include "suites/case_result.hpp"
#include "suites/problem_descriptor.hpp"

namespace cs::suites {

/// The descriptor of `id`.
const ProblemDescriptor& problem_descriptor(ProblemId id);

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

/// The default value of every settable parameter of the problems that have a case in `cases`.
std::map<ProblemId, std::map<std::string, double>> parameter_defaults(
    const std::vector<CaseResult>& cases);

}  // namespace cs::suites

#pragma once
// The solvers of a results document and, per solver, the row of one of the study's option sets
// (for the cross-code comparison, generic over any number of solvers). A solver's row is the one
// with the study's settings (a discretized target, no parameter overrides) and, for our solver,
// patch-recovered nodal stresses (the baseline row); another solver's nodal stresses are its own,
// whatever the case's `recovery` says, so its row of either recovery counts (spr first).

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The solver label of our solver in results.json ("builtin").
std::string builtin_solver_label();

/// The solvers of the document's cases, ours first, then the others in order of their names:
/// {"builtin", "calculix"}.
std::vector<std::string> solvers_in(const ResultsIndex& index);

/// How the report names a solver: "ours" for the built-in solver, else the label its results
/// carry (an imported code's name, a registered code's "calculix:hard-ss").
std::string solver_display_name(const std::string& solver);

/// True when the document has cases of more than one solver.
bool is_cross_code(const ResultsIndex& index);

/// The row of `solver` for (problem, quantity, element, option) with the study's settings, or
/// nullptr.
const schema::RowVerdict* solver_row(const ResultsIndex& index, const std::string& solver,
                                     schema::ProblemId problem, schema::Quantity quantity,
                                     schema::Element element, const Option& option);

/// The option sets any solver other than ours has a row of, for (problem, quantity, element),
/// in all_options() order.
std::vector<Option> cross_code_options(const ResultsIndex& index, schema::ProblemId problem,
                                       schema::Quantity quantity, schema::Element element);

/// A case's id without its solver and recovery fields: the key under which the same case of
/// two solvers is matched ("H_p/F/Q4/PM/ss").
std::string same_case_key(const schema::CaseSpec& spec);

}  // namespace cs::reports

#pragma once
// The codes of a results document: ours ("builtin") first, then the others by name. A code is
// the part of a case's solver label before ':' ("calculix" of "calculix:hard-ss"); what follows
// is the code's own label of its option ("hard-ss"). An imported code without a label is a code
// of one option.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The solver label of our solver in results.json ("builtin").
std::string builtin_solver_label();

/// The code of a case: "builtin", "calculix", "getfem", an imported code's name.
std::string code_of(const schema::CaseSpec& spec);

/// The code's own label of the case's option: "hard-ss"; ours (and an imported code without a
/// label): the study's option set, "PM ss".
std::string option_label_of(const schema::CaseSpec& spec);

/// The codes of the document's cases, ours first, then the others in order of their names:
/// {"builtin", "calculix", "getfem"}.
std::vector<std::string> solvers_in(const ResultsIndex& index);

/// How the report names a code: "ours" for the built-in solver, else its name.
std::string solver_display_name(const std::string& code);

/// The solvers whose cases the results hold, as a reader knows them: "ours", "ours and
/// CalculiX" (`last` joins the last two).
std::string solver_names(const ResultsIndex& index, const char* last = " and ");

/// True when the document has cases of more than one code.
bool is_cross_code(const ResultsIndex& index);

}  // namespace cs::reports

#pragma once
// The case axes as the suites layer uses them. The vocabulary (enums, names, the case id) is
// the schema's (schema/case_axes.hpp, schema/case_spec.hpp); this header brings it into
// cs::suites and adds what only the suites need: the element as the solver's type, the study's
// discretizations and the `--set` parser.

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "schema/case_spec.hpp"
#include "solver/mesh/mesh.hpp"

namespace cs::suites {

using schema::Algorithm;
using schema::case_id;
using schema::CaseSpec;
using schema::ContactKind;
using schema::Element;
using schema::MeshLevel;
using schema::parse;
using schema::ProblemId;
using schema::Recovery;
using schema::SolverKind;
using schema::TargetKind;
using schema::to_string;
using schema::values;
using solver::ElementType;

/// The solver's element type of a case's element.
constexpr ElementType to_solver(Element e) {
  return e == Element::Q8 ? ElementType::Q8 : ElementType::Q4;
}

/// ss and ns: the study's discretizations (mortar is a further option).
const std::vector<ContactKind>& study_contacts();

/// Parses one `--set name=value` argument, the value a number or a ratio of two (1/3); -0 is
/// read as 0. Throws SuiteInputError on a malformed one (no '=', an empty name, a value that is
/// not a finite double or under/overflows it, a ratio that does).
std::pair<std::string, double> parse_override(std::string_view text);

/// Parses every `--set` argument into one map; a key given twice is an error (the first value
/// would silently win otherwise).
std::map<std::string, double> parse_overrides(const std::vector<std::string>& texts);

/// `text` as a file or directory name: every character outside [A-Za-z0-9._=@-] as '_'
/// (case ids name CalculiX's case directories and export's model directories).
std::string plain_file_name(std::string_view text);

/// Throws SuiteInputError if a comma-separated option list (`--problems`, ...) has an empty item.
void require_no_empty_items(const std::vector<std::string>& items, std::string_view option);

/// The items of a comma-separated list option given once or more (`--problems H_p,S_1
/// --problems P_p`), in order; split here rather than by CLI11, which drops empty items:
/// "H_p,,S_1" throws SuiteInputError (require_no_empty_items), it is not read as "H_p,S_1".
std::vector<std::string> split_list_option(const std::vector<std::string>& raw,
                                           std::string_view option);

}  // namespace cs::suites

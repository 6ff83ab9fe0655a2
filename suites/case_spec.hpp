#pragma once
// The case axes as the suites layer uses them. The vocabulary (enums, names, the case id) is
// the schema's (schema/case_axes.hpp, schema/case_spec.hpp); this header brings it into
// cs::suites and adds what only the suites need: the element as the solver's type, the study's
// discretizations and the `--set` parser.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "schema/case_spec.hpp"
#include "solver/mesh/mesh.hpp"

namespace cs::suites {

using schema::Algorithm;
using schema::CaseSpec;
using schema::ContactKind;
using schema::Element;
using schema::MeshLevel;
using schema::ProblemId;
using schema::Recovery;
using schema::SolverKind;
using schema::TargetKind;
using schema::case_id;
using schema::parse;
using schema::to_string;
using schema::values;
using solver::ElementType;

/// The solver's element type of a case's element.
constexpr ElementType to_solver(Element e) {
  return e == Element::Q8 ? ElementType::Q8 : ElementType::Q4;
}

/// ss and ns: the study's discretizations (mortar is a further option).
const std::vector<ContactKind>& study_contacts();

/// Parses one `--set name=value` argument; throws SuiteInputError on a malformed one.
std::pair<std::string, double> parse_override(std::string_view text);

}  // namespace cs::suites

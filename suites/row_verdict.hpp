#pragma once
// The study's unit of assessment (schema/row_verdict.hpp), assembled: cases that differ only in
// mesh level form one row per quantity, graded on the finest mesh present (Eq. 46) and checked
// for convergence or, for the singular problems, divergence (Eq. 47), by the rules of grading/.

#include <string>
#include <vector>

#include "schema/row_verdict.hpp"
#include "suites/case_result.hpp"

namespace cs::suites {

using schema::RowVerdict;

/// The id of the row of `quantity` that a case of `spec` belongs to: case_key(spec) + "/" +
/// quantity, e.g. "H_p/Q4/LMP/ss/sigma_c".
std::string row_id(const CaseSpec& spec, Quantity quantity);

/// Groups the cases into rows (cases that differ only in mesh level) and applies the verdicts.
/// Cases with status `failed` or `timeout` leave their mesh empty in the row.
std::vector<RowVerdict> make_row_verdicts(const std::vector<CaseResult>& cases);

}  // namespace cs::suites

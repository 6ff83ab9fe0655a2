#pragma once
// What one analysis produced (the schema's record, schema/case_result.hpp), in cs::suites.

#include "schema/case_result.hpp"
#include "schema/grade.hpp"
#include "suites/case_spec.hpp"

namespace cs::suites {

using schema::CaseResult;
using schema::CaseStatus;
using schema::ExactProfile;
using schema::Grade;
using schema::is_worse;
using schema::Quantity;
using schema::QuantityResult;
using schema::SurfaceProfile;

}  // namespace cs::suites

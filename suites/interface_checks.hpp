#pragma once
// The interface checks of a case (schema/interface_checks.hpp) from the built-in solver's
// contact solution: the nodal contact forces against the applied load, the most tensile
// pressure, the pressure beyond the exact contact patch, the deepest penetration.

#include "schema/interface_checks.hpp"
#include "solver/contact/contact_result.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// `applied_load` is the load the interface must carry (the sum of the z components of the
/// external loads, or a rigid punch's target load), in the units of the nodal contact forces;
/// <= 0 or non-finite: no force balance (e.g. a problem loaded in steps).
schema::InterfaceChecks check_interface(const ProblemSetup& setup,
                                        const solver::ContactResult& contact, double applied_load);

}  // namespace cs::suites

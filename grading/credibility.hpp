#pragma once
// Whether a row's graded value can be believed, whatever its error: the F case's contact
// interface must be physically sound (grading/interface_check_rules.hpp).

#include <string>
#include <vector>

#include "schema/interface_checks.hpp"

namespace cs::grading {

struct Credibility {
  bool credible = true;
  std::vector<std::string> failures;  ///< the checks that make it not credible, by name
};

/// Not credible when the case (a row's F case) fails force balance (the interface does not
/// carry the load), carries tensile pressure (a frictionless contact pulls) or presses more than
/// one element outside the exact patch, with the tolerances of schema/interface_checks.hpp.
/// Penetration is reported by the interface checks but does not make a row not credible: a
/// penalty method penetrates by design, and its effect on the graded value is in the error.
/// Absent checks do not fail.
Credibility credibility(const schema::InterfaceChecks& checks);

}  // namespace cs::grading

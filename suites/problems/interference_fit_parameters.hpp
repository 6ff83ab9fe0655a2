#pragma once
// The settable parameters of the interference fits IF_p and IF_a (suites/problems/
// interference_fit.cpp).

#include <algorithm>
#include <vector>

#include "suites/problems/problem_builders.hpp"

namespace cs::suites::problems {

/// The study's parameters without p_over_E (E is chosen so that the exact pressure is 1), with
/// E_ratio (the shaft's modulus over the ring's) 1 by default, then delta_over_b and b_over_c.
inline std::vector<ParameterSpec> interference_fit_parameters() {
  auto params = with_default(study_parameters({}), "E_ratio", 1.0);
  std::erase_if(params, [](const ParameterSpec& s) { return s.name == "p_over_E"; });
  // Accepted up to 1 here so that the oracle itself refuses delta/b > 1e-2 with its reason
  // (require_small_interference, called when the case is validated).
  params.push_back({"delta_over_b", 1e-3, 0.0, 1.0, false, true,
                    "radial interference over the bore radius b (the oracle's small-strain "
                    "limit: delta/b <= 1e-2; the answers are linear in it)"});
  params.push_back({"b_over_c", 0.5, 0.05, 0.9, true, true,
                    "bore radius over the ring's (shell's) outer radius c"});
  return params;
}

/// Throws SuiteInputError "IF_p: ... interference delta/b = 0.02 exceeds 1e-2, the small-strain
/// limit of the oracle ..." when the oracle refuses the fit of `params`.
void require_small_interference(const CaseSpec& spec, const Parameters& params);

}  // namespace cs::suites::problems

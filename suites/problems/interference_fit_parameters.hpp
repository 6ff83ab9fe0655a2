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
  // (require_small_interference, called when the case is validated). Below about 1e-11 the
  // interference drowns in the round-off of the coordinates (IF_a C LMP ss: p_mean +0.225 % from
  // 1e-10 to 1e-8, +0.233 % at 1e-12, -75.8 % at 1e-16, +4e5 % at 1e-20): 1e-9 leaves a margin.
  params.push_back({"delta_over_b", 1e-3, 1e-9, 1.0, true, true,
                    "radial interference over the bore radius b (the oracle's small-strain "
                    "limit: delta/b <= 1e-2; the answers are linear in it; below 1e-9 "
                    "round-off takes over)"});
  params.push_back({"b_over_c", 0.5, 0.05, 0.9, true, true,
                    "bore radius over the ring's (shell's) outer radius c"});
  return params;
}

/// Throws SuiteInputError "IF_p: ... interference delta/b = 0.02 exceeds 1e-2, the small-strain
/// limit of the oracle ..." when the oracle refuses the fit of `params`.
void require_small_interference(const CaseSpec& spec, const Parameters& params);

}  // namespace cs::suites::problems

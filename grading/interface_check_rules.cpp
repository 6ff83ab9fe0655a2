#include "grading/interface_check_rules.hpp"

#include <cmath>

namespace cs::grading {

const std::array<InterfaceCheckRule, 4>& interface_check_rules() {
  static const std::array<InterfaceCheckRule, 4> rules{{
      {"force balance", "|Σ nodal contact forces − load| / load", schema::kForceBalanceTolerance,
       true,
       [](const schema::InterfaceChecks& c) -> std::optional<double> {
         return c.force_balance ? std::optional(std::abs(*c.force_balance)) : std::nullopt;
       }},
      {"tensile pressure", "largest tensile contact traction / p", schema::kTensileTolerance, true,
       [](const schema::InterfaceChecks& c) { return c.max_tensile_over_p; }},
      {"pressure outside the patch",
       "largest contact pressure / p more than one element beyond the exact patch",
       schema::kOutsideTolerance, true,
       [](const schema::InterfaceChecks& c) { return c.max_outside_over_p; }},
      {"penetration", "largest penetration / element size at the contact",
       schema::kPenetrationTolerance, false,
       [](const schema::InterfaceChecks& c) { return c.max_penetration_over_h; }},
  }};
  return rules;
}

bool fails(const InterfaceCheckRule& rule, double measured) {
  return !(measured <= rule.tolerance);
}

std::vector<std::string> interface_failures(const schema::InterfaceChecks& checks) {
  std::vector<std::string> out;
  for (const auto& rule : interface_check_rules()) {
    const auto v = rule.measure(checks);
    if (v && fails(rule, *v))
      out.emplace_back(rule.name);
  }
  return out;
}

}  // namespace cs::grading

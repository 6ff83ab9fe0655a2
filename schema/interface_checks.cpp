#include "schema/interface_checks.hpp"

#include <cmath>

namespace cs::schema {

std::vector<std::string> InterfaceChecks::failures() const {
  std::vector<std::string> out;
  if (force_balance && !(std::abs(*force_balance) <= kForceBalanceTolerance))
    out.emplace_back("force balance");
  if (max_tensile_over_p && !(*max_tensile_over_p <= kTensileTolerance))
    out.emplace_back("tensile pressure");
  if (max_outside_over_p && !(*max_outside_over_p <= kOutsideTolerance))
    out.emplace_back("pressure outside the patch");
  if (max_penetration_over_h && !(*max_penetration_over_h <= kPenetrationTolerance))
    out.emplace_back("penetration");
  return out;
}

}  // namespace cs::schema

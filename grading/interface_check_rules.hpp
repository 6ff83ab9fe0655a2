#pragma once
// When an interface check of one case (schema/interface_checks.hpp: the measures and their
// tolerances) fails. A check fails when its measure exceeds its tolerance; an absent check
// (one that does not apply to the case) does not fail.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "schema/interface_checks.hpp"

namespace cs::grading {

/// One check: its name, its tolerance, whether its failure makes a row not credible
/// (grading/credibility.hpp), and the measure compared with the tolerance.
struct InterfaceCheckRule {
  std::string_view name;          ///< "force balance", "tensile pressure", ...
  std::string_view measure_text;  ///< what `measure` is, in words
  double tolerance = 0.0;
  bool bears_on_credibility = true;
  /// The measure: |force_balance|, max_tensile_over_p, max_outside_over_p or
  /// max_penetration_over_h; empty where the check is absent.
  std::optional<double> (*measure)(const schema::InterfaceChecks&) = nullptr;
};

/// The four checks, in the order reports list them: force balance
/// (schema::kForceBalanceTolerance), tensile pressure (kTensileTolerance), pressure outside the
/// patch (kOutsideTolerance), penetration (kPenetrationTolerance; reported, not bearing on
/// credibility).
const std::array<InterfaceCheckRule, 4>& interface_check_rules();

/// True when `measured` fails the rule: !(measured <= rule.tolerance) (NaN fails).
bool fails(const InterfaceCheckRule& rule, double measured);

/// The names of the checks that fail, in rule order.
std::vector<std::string> interface_failures(const schema::InterfaceChecks& checks);

}  // namespace cs::grading

#include "grading/credibility.hpp"

#include "grading/interface_check_rules.hpp"

namespace cs::grading {

Credibility credibility(const schema::InterfaceChecks& checks) {
  Credibility out;
  for (const auto& rule : interface_check_rules()) {
    if (!rule.bears_on_credibility)
      continue;
    const auto v = rule.measure(checks);
    if (v && fails(rule, *v))
      out.failures.emplace_back(rule.name);
  }
  out.credible = out.failures.empty();
  return out;
}

}  // namespace cs::grading

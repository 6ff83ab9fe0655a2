#include "suites/friction_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "grading/accuracy.hpp"

namespace cs::suites {
namespace {

using solver::FrictionState;

/// The stick-slip boundary on one side: nodes ordered from x = 0 outwards.
std::optional<double> side_edge(const std::vector<const solver::ContactNodeResult*>& outwards) {
  std::optional<double> last_stick;
  for (const auto* n : outwards) {
    const double r = std::abs(n->position.x());
    if (n->friction == FrictionState::Stick) {
      last_stick = r;
    } else if (n->friction == FrictionState::Slip && last_stick) {
      return 0.5 * (*last_stick + r);
    }
  }
  return last_stick;
}

}  // namespace

double stick_half_width(const std::vector<solver::ContactNodeResult>& nodes) {
  std::vector<const solver::ContactNodeResult*> right, left;
  for (const auto& n : nodes) {
    if (!n.closed)
      continue;
    (n.position.x() >= 0.0 ? right : left).push_back(&n);
  }
  auto by_distance = [](const auto* u, const auto* v) {
    return std::abs(u->position.x()) < std::abs(v->position.x());
  };
  std::sort(right.begin(), right.end(), by_distance);
  std::sort(left.begin(), left.end(), by_distance);
  const auto r = side_edge(right), l = side_edge(left);
  if (r && l)
    return 0.5 * (*r + *l);
  return r ? *r : (l ? *l : 0.0);
}

bool sampled_from_contact(SamplePoint where) {
  return where == SamplePoint::StickZoneEdge || where == SamplePoint::ContactPeakShear;
}

QuantityResult contact_quantity(const QuantityRule& rule, const solver::ContactResult& contact,
                                double a, double p) {
  QuantityResult q;
  q.quantity = rule.quantity;
  q.exact = rule.exact;
  q.study_exact = rule.study_exact;
  q.value = rule.where == SamplePoint::StickZoneEdge ? stick_half_width(contact.nodes) / a
                                                     : contact.peak_shear / p;
  q.error_percent = grading::error_percent(q.value, rule.exact);
  q.grade = grading::grade_of_error(q.error_percent);
  return q;
}

}  // namespace cs::suites

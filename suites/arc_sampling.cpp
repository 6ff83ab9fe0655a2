#include "suites/arc_sampling.hpp"

#include <cmath>

#include "grading/accuracy.hpp"

namespace cs::suites {

bool sampled_along_arc(SamplePoint where) {
  return where == SamplePoint::InterfaceMeanPressure || where == SamplePoint::ArcPressureExtreme;
}

double mean_pressure_over_exact(const solver::ContactResult& contact, const ProblemSetup& setup) {
  if (!(setup.exact_interface_force > 0.0))
    return std::nan("");
  return contact.total_normal_force / setup.exact_interface_force;
}

double extreme_pressure_over_exact(const solver::ContactResult& contact, double p) {
  double extreme = std::nan("");
  for (const auto& n : contact.nodes) {
    const double ratio = n.pressure / p;
    if (!(std::abs(ratio - 1.0) <= std::abs(extreme - 1.0)))  // NaN extreme: take the first
      extreme = ratio;
  }
  return extreme;
}

QuantityResult arc_quantity(const QuantityRule& rule, const solver::ContactResult& contact,
                            const ProblemSetup& setup) {
  QuantityResult q;
  q.quantity = rule.quantity;
  q.exact = rule.exact;
  q.study_exact = rule.study_exact;
  q.value = rule.where == SamplePoint::InterfaceMeanPressure
                ? mean_pressure_over_exact(contact, setup)
                : extreme_pressure_over_exact(contact, setup.p);
  q.error_percent = grading::error_percent(q.value, rule.exact);
  q.grade = grading::grade_of_error(q.error_percent);
  return q;
}

}  // namespace cs::suites

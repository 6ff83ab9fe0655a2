#include "apps/model_cost.hpp"

#include <algorithm>

#include "suites/problem_catalog.hpp"
#include "suites/study_meshes.hpp"

namespace cs::apps {

double group_cost(const suites::CaseSpec& spec) {
  const double f = suites::level_factor(spec.mesh);  // elements grow as f^2
  const double cost = f * f * suites::problem_descriptor(spec.problem).relative_cost;
  return spec.element == schema::Element::Q8 ? 3.0 * cost : cost;
}

int model_threads(const suites::CaseSpec& spec, int cores) {
  return group_cost(spec) >= kThreadedCost ? std::max(1, cores) : 1;
}

}  // namespace cs::apps

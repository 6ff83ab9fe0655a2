#include "apps/model_cost.hpp"

#include "suites/problem_catalog.hpp"
#include "suites/study_meshes.hpp"

namespace cs::apps {

double group_cost(const suites::CaseSpec& spec) {
  const double f = suites::level_factor(spec.mesh);  // elements grow as f^2
  const double cost = f * f * suites::problem_descriptor(spec.problem).relative_cost;
  return spec.element == schema::Element::Q8 ? 3.0 * cost : cost;
}

}  // namespace cs::apps

#include "grading/grade_change.hpp"

#include <algorithm>
#include <cmath>

#include "grading/accuracy.hpp"
#include "schema/baseline_file.hpp"

namespace cs::grading {

double relative_drift(double a, double b) {
  return std::abs(b - a) / std::max(std::abs(a), 1e-300);
}

double round_off_tolerance(double quantity_tolerance) {
  return std::min(quantity_tolerance, schema::kDefaultGateTolerance);
}

bool grade_change_is_round_off(const GradedValue& before, const GradedValue& after,
                               double tolerance) {
  if (!before.value || !after.value || !before.error || !after.error ||
      !(relative_drift(*before.value, *after.value) <= tolerance))
    return false;
  const schema::Grade a = grade_of_error(*before.error), b = grade_of_error(*after.error);
  const schema::Grade better = std::min(a, b), worse = std::max(a, b);  // ordered best first
  if (better == worse || better == schema::Grade::u ||
      static_cast<int>(worse) - static_cast<int>(better) != 1)
    return false;
  const double bound = grade_upper_bound(better);
  const double edge = 100.0 * tolerance * (1.0 + bound / 100.0) * (1.0 + 1e-9);
  return std::abs(std::abs(*before.error) - bound) <= edge &&
         std::abs(std::abs(*after.error) - bound) <= edge;
}

bool grade_change_is_round_off(const schema::RowVerdict& before, const schema::RowVerdict& after,
                               double tolerance) {
  if (!before.graded_mesh || before.graded_mesh != after.graded_mesh)
    return false;
  const auto i = static_cast<std::size_t>(*before.graded_mesh);
  return grade_change_is_round_off({before.values[i], before.errors[i]},
                                   {after.values[i], after.errors[i]}, tolerance);
}

}  // namespace cs::grading

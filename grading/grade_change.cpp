#include "grading/grade_change.hpp"

#include <algorithm>
#include <cmath>

namespace cs::grading {

double relative_drift(double a, double b) {
  return std::abs(b - a) / std::max(std::abs(a), 1e-300);
}

bool grade_change_is_round_off(std::optional<double> a, std::optional<double> b, double tolerance) {
  return a && b && relative_drift(*a, *b) <= tolerance;
}

bool grade_change_is_round_off(const schema::RowVerdict& before, const schema::RowVerdict& after,
                               double tolerance) {
  if (!before.graded_mesh || before.graded_mesh != after.graded_mesh)
    return false;
  const auto i = static_cast<std::size_t>(*before.graded_mesh);
  return grade_change_is_round_off(before.values[i], after.values[i], tolerance);
}

}  // namespace cs::grading

#include "grading/accuracy.hpp"

#include <algorithm>
#include <cmath>

namespace cs::grading {

double error_percent(double value, double exact) {
  return 100.0 * (value - exact) / std::abs(exact);
}

namespace {

/// Eq. 46's upper bounds (|e| in %) of e, g and s.
constexpr double kBounds[] = {1.0, 5.0, 10.0};

/// A read's resolution, 0 for a point, widened by round-off: an edge at a node reads exactly
/// half a node off, and equality within round-off counts as within the resolution.
double widened(double resolution_percent) {
  return resolution_percent > 0.0 ? resolution_percent * (1.0 + 1e-9) : 0.0;
}

}  // namespace

schema::Grade grade_of_error(double error_percent) {
  const double e = std::abs(error_percent);
  if (!(e < kBounds[2]))
    return schema::Grade::u;  // also catches NaN
  if (e < kBounds[0])
    return schema::Grade::e;
  return e < kBounds[1] ? schema::Grade::g : schema::Grade::s;
}

bool read_settles_grade(double error_percent, double resolution_percent) {
  if (!(resolution_percent > 0.0))
    return true;
  const double e = std::abs(error_percent), r = widened(resolution_percent);
  return e > r && grade_of_error(e - r) == grade_of_error(e + r);
}

schema::Grade best_reading_grade(double error_percent, double resolution_percent) {
  const double r = widened(resolution_percent);
  return grade_of_error(std::isnan(error_percent) ? error_percent
                                                  : std::max(std::abs(error_percent) - r, 0.0));
}

schema::Grade worst_reading_grade(double error_percent, double resolution_percent) {
  const double r = widened(resolution_percent);
  return grade_of_error(std::abs(error_percent) + r);
}

std::optional<bool> read_at_least(double error_percent, double resolution_percent,
                                  schema::Grade grade) {
  if (!schema::is_worse(worst_reading_grade(error_percent, resolution_percent), grade))
    return true;
  if (schema::is_worse(best_reading_grade(error_percent, resolution_percent), grade))
    return false;
  return std::nullopt;
}

double grade_upper_bound(schema::Grade grade) {
  const auto i = static_cast<std::size_t>(grade);
  return i < std::size(kBounds) ? kBounds[i] : INFINITY;
}

double grade_band_width(schema::Grade grade) {
  switch (grade) {
    case schema::Grade::e:
      return kBounds[0];
    case schema::Grade::g:
      return kBounds[1] - kBounds[0];
    case schema::Grade::s:
      return kBounds[2] - kBounds[1];
    case schema::Grade::u:
      break;
  }
  return INFINITY;
}

bool values_coincide(double a, double b) {
  return std::abs(a - b) <= kCoincidenceRelative * std::max(std::abs(a), std::abs(b));
}

}  // namespace cs::grading

#include "grading/accuracy.hpp"

#include <algorithm>
#include <cmath>

namespace cs::grading {

double error_percent(double value, double exact) {
  return 100.0 * (value - exact) / std::abs(exact);
}

schema::Grade grade_of_error(double error_percent) {
  const double e = std::abs(error_percent);
  if (!(e < 10.0))
    return schema::Grade::u;  // also catches NaN
  if (e < 1.0)
    return schema::Grade::e;
  return e < 5.0 ? schema::Grade::g : schema::Grade::s;
}

bool values_coincide(double a, double b) {
  return std::abs(a - b) <= kCoincidenceRelative * std::max(std::abs(a), std::abs(b));
}

}  // namespace cs::grading

#include "suites/grading.hpp"

#include <cmath>

namespace cs::suites {

double error_percent(double value, double exact) {
  return 100.0 * (value - exact) / std::abs(exact);
}

Grade grade_from_error(double error_percent) {
  return schema::grade_of_error(error_percent);
}

bool is_converging(double error_c, double error_m, double error_f) {
  const double c = std::abs(error_c);
  const double m = std::abs(error_m);
  const double f = std::abs(error_f);
  if (!std::isfinite(c) || !std::isfinite(m) || !std::isfinite(f))
    return false;
  constexpr double tol = kErrorResolutionPercent;
  const bool never_grows = m <= c + tol && f <= m + tol;
  const bool improves_or_exact = f < c - tol || c <= tol;
  return never_grows && improves_or_exact;
}

bool is_diverging(double value_c, double value_m, double value_f) {
  return std::abs(value_c - value_m) < std::abs(value_m - value_f);
}

}  // namespace cs::suites

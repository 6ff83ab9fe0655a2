#include "grading/richardson.hpp"

#include <algorithm>
#include <cmath>

namespace cs::grading {
namespace {

/// Relative size below which a difference of two values is round-off.
constexpr double kRoundOff = 1e-12;
/// Roache's safety factor for a three-grid study.
constexpr double kGciSafetyFactor = 1.25;

}  // namespace

schema::ErrorEstimate error_estimate(double f_c, double f_m, double f_f) {
  schema::ErrorEstimate out;
  const double d1 = f_c - f_m, d2 = f_m - f_f;
  const double scale = std::max({std::abs(f_c), std::abs(f_m), std::abs(f_f)});
  if (std::abs(d1) <= kRoundOff * scale || std::abs(d2) <= kRoundOff * scale) {
    out.note = "differences at round-off";
    return out;
  }
  if (d1 * d2 < 0.0) {
    out.note = "oscillatory";
    return out;
  }
  if (std::abs(d1) <= std::abs(d2)) {
    out.note = "differences do not shrink";
    return out;
  }
  const double p = std::log2(std::abs(d1) / std::abs(d2));
  const double denominator = std::exp2(p) - 1.0;
  out.asymptotic = true;
  out.observed_order = p;
  out.richardson = f_f + (f_f - f_m) / denominator;
  if (f_f != 0.0)
    out.gci_percent = kGciSafetyFactor * std::abs(d2 / f_f) / denominator * 100.0;
  return out;
}

}  // namespace cs::grading

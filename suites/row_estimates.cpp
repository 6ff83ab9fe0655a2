#include "suites/row_estimates.hpp"

#include <algorithm>
#include <cmath>

#include "suites/grading.hpp"

namespace cs::suites {
namespace {

/// Relative size below which a difference of two values is round-off.
constexpr double kRoundOff = 1e-12;

std::optional<double> order_of(const std::optional<double>& coarse,
                               const std::optional<double>& fine) {
  if (!coarse || !fine)
    return std::nullopt;
  const double c = std::abs(*coarse), f = std::abs(*fine);
  if (c < schema::kErrorNoiseFloorPercent || f < schema::kErrorNoiseFloorPercent)
    return std::nullopt;
  return std::log2(c / f);
}

}  // namespace

std::array<std::optional<double>, 2> pair_orders(const std::array<std::optional<double>, 3>& e) {
  return {order_of(e[0], e[1]), order_of(e[1], e[2])};
}

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
    out.gci_percent = 1.25 * std::abs(d2 / f_f) / denominator * 100.0;
  return out;
}

}  // namespace cs::suites

#include "reports/figures/observed_order.hpp"

#include <algorithm>
#include <cmath>

namespace cs::reports {

std::optional<double> observed_order(const std::vector<SizePoint>& points) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& p : points) {
    if (!(p.h > 0) || !(p.y > 0) || !std::isfinite(p.h) || !std::isfinite(p.y))
      continue;
    const double x = std::log(p.h), y = std::log(p.y);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (n < 2)
    return std::nullopt;
  const double denominator = n * sxx - sx * sx;
  if (std::abs(denominator) <= 1e-12 * std::max(1.0, n * sxx))
    return std::nullopt;
  return (n * sxy - sx * sy) / denominator;
}

}  // namespace cs::reports

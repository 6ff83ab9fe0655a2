#include "solver/elements/gauss_rule.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cs::solver {
namespace {

void check_order(int n) {
  if (n < 1 || n > kMaxGaussPoints) {
    throw std::invalid_argument("Gauss rule: " + std::to_string(n) +
                                " points requested (supported: 1 to " +
                                std::to_string(kMaxGaussPoints) + ")");
  }
}

/// P_n(x) and P_n'(x) by the three-term recurrence.
std::pair<double, double> legendre(int n, double x) {
  double p0 = 1.0;
  double p1 = x;
  if (n == 0)
    return {1.0, 0.0};
  for (int k = 2; k <= n; ++k) {
    const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  const double dp = n * (x * p1 - p0) / (x * x - 1.0);
  return {p1, dp};
}

GaussRule1D make_rule_1d(int n) {
  GaussRule1D rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    // Chebyshev-like initial guess of the i-th root (descending), then Newton.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    for (int it = 0; it < 100; ++it) {
      const auto [p, dp] = legendre(n, x);
      const double dx = p / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16)
        break;
    }
    const auto [p, dp] = legendre(n, x);
    (void)p;
    // Roots come out in descending order; store ascending.
    rule.points[n - 1 - i] = x;
    rule.weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  if (n % 2 == 1)
    rule.points[n / 2] = 0.0;  // exact zero at the middle
  return rule;
}

GaussRule2D make_rule_2d(int n) {
  const GaussRule1D& g = gauss_rule_1d(n);
  GaussRule2D rule;
  rule.points_per_direction = n;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      rule.points.emplace_back(g.points[i], g.points[j]);
      rule.weights.push_back(g.weights[i] * g.weights[j]);
    }
  }
  return rule;
}

template <typename Rule, typename Make>
const Rule& cached(int n, Make make) {
  // Built once, on first use of any order (thread-safe static initialization).
  static const std::array<Rule, kMaxGaussPoints> rules = [&] {
    std::array<Rule, kMaxGaussPoints> all;
    for (int k = 1; k <= kMaxGaussPoints; ++k)
      all[k - 1] = make(k);
    return all;
  }();
  return rules[n - 1];
}

}  // namespace

const GaussRule1D& gauss_rule_1d(int n) {
  check_order(n);
  return cached<GaussRule1D>(n, make_rule_1d);
}

const GaussRule2D& gauss_rule_2d(int n) {
  check_order(n);
  return cached<GaussRule2D>(n, make_rule_2d);
}

}  // namespace cs::solver

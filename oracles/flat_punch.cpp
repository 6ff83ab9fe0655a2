#include "oracles/flat_punch.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "oracles/invalid_input.hpp"

namespace cs::oracles {
namespace {

void require_punch(const char* where, double a, double P) {
  require_positive(where, "punch half-width (radius) a", a);
  require_positive(where, "load P", P);
}

[[noreturn]] void throw_at_edge(const char* where, const char* what, double at) {
  throw InvalidInput(std::string(where) + ": the pressure is unbounded at the punch edge (got " +
                     what + " = " + format_value(at) + ", at the edge a)");
}

/// (a^2 - s^2)^(1/2) for 0 <= s < a, without cancellation near the edge.
double edge_root(double a, double s) {
  return std::sqrt((a - s) * (a + s));
}

}  // namespace

double sadowsky_mean_pressure(const SadowskyPunch& punch) {
  require_punch("sadowsky_mean_pressure", punch.a, punch.P);
  return punch.P / (2.0 * punch.a);
}

double sadowsky_pressure(const SadowskyPunch& punch, double x) {
  constexpr const char* kWhere = "sadowsky_pressure";
  require_punch(kWhere, punch.a, punch.P);
  require_finite(kWhere, "position x", x);
  const double s = std::abs(x);
  if (s == punch.a)
    throw_at_edge(kWhere, "x", x);
  if (s > punch.a)
    return 0.0;
  return punch.P / (std::numbers::pi * edge_root(punch.a, s));
}

double harding_sneddon_mean_pressure(const HardingSneddonPunch& punch) {
  require_punch("harding_sneddon_mean_pressure", punch.a, punch.P);
  return punch.P / (std::numbers::pi * punch.a * punch.a);
}

double harding_sneddon_pressure(const HardingSneddonPunch& punch, double r) {
  constexpr const char* kWhere = "harding_sneddon_pressure";
  require_punch(kWhere, punch.a, punch.P);
  require_non_negative(kWhere, "radius r", r);
  if (r == punch.a)
    throw_at_edge(kWhere, "r", r);
  if (r > punch.a)
    return 0.0;
  return punch.P / (2.0 * std::numbers::pi * punch.a * edge_root(punch.a, r));
}

}  // namespace cs::oracles

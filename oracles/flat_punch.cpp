#include "oracles/flat_punch.hpp"

#include <cmath>
#include <limits>
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

/// (1 - (s/a)^2)^(1/2) for 0 <= s < a, without cancellation near the edge (a - s is exact
/// there) and without overflow of a + s.
double edge_root(double a, double s) {
  return std::sqrt((a - s) / a * (1.0 + s / a));
}

/// The pressure scale P/a (plane) or P/a^2 (circular), refused unless a normal double.
double pressure_scale(const char* where, double P, double a, int power) {
  double scale = P / a;
  if (power == 2)
    scale /= a;
  if (!(scale >= std::numeric_limits<double>::min()) || !std::isfinite(scale)) {
    throw InvalidInput(std::string(where) + ": the pressure scale P/a" + (power == 2 ? "^2" : "") +
                       " = " + format_value(scale) + " (P = " + format_value(P) +
                       ", a = " + format_value(a) + ") is out of floating-point range");
  }
  return scale;
}

/// `pressure` unless it overflowed (a huge scale right next to the edge).
double finite_pressure(const char* where, double pressure, double at) {
  if (!std::isfinite(pressure)) {
    throw InvalidInput(std::string(where) + ": the pressure at " + format_value(at) +
                       " is out of floating-point range (too close to the edge for this load)");
  }
  return pressure;
}

}  // namespace

double sadowsky_mean_pressure(const SadowskyPunch& punch) {
  constexpr const char* kWhere = "sadowsky_mean_pressure";
  require_punch(kWhere, punch.a, punch.P);
  return 0.5 * pressure_scale(kWhere, punch.P, punch.a, 1);
}

double sadowsky_pressure(const SadowskyPunch& punch, double x) {
  constexpr const char* kWhere = "sadowsky_pressure";
  require_punch(kWhere, punch.a, punch.P);
  require_finite(kWhere, "position x", x);
  const double scale = pressure_scale(kWhere, punch.P, punch.a, 1);
  const double s = std::abs(x);
  if (s == punch.a)
    throw_at_edge(kWhere, "x", x);
  if (s > punch.a)
    return 0.0;
  return finite_pressure(kWhere, scale / (std::numbers::pi * edge_root(punch.a, s)), x);
}

double harding_sneddon_mean_pressure(const HardingSneddonPunch& punch) {
  constexpr const char* kWhere = "harding_sneddon_mean_pressure";
  require_punch(kWhere, punch.a, punch.P);
  return pressure_scale(kWhere, punch.P, punch.a, 2) / std::numbers::pi;
}

double harding_sneddon_pressure(const HardingSneddonPunch& punch, double r) {
  constexpr const char* kWhere = "harding_sneddon_pressure";
  require_punch(kWhere, punch.a, punch.P);
  require_non_negative(kWhere, "radius r", r);
  const double scale = pressure_scale(kWhere, punch.P, punch.a, 2);
  if (r == punch.a)
    throw_at_edge(kWhere, "r", r);
  if (r > punch.a)
    return 0.0;
  return finite_pressure(kWhere, scale / (2.0 * std::numbers::pi * edge_root(punch.a, r)), r);
}

}  // namespace cs::oracles

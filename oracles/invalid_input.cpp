#include "oracles/invalid_input.hpp"

#include <charconv>
#include <cmath>

namespace cs::oracles {

std::string format_value(double value) {
  if (std::isnan(value))
    return "nan";
  if (std::isinf(value))
    return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

void require_positive(std::string_view where, std::string_view what, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InvalidInput(std::string(where) + ": " + std::string(what) +
                       " must be positive and finite (got " + format_value(value) + ")");
  }
}

void require_non_negative(std::string_view where, std::string_view what, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InvalidInput(std::string(where) + ": " + std::string(what) +
                       " must be >= 0 and finite (got " + format_value(value) + ")");
  }
}

void require_finite(std::string_view where, std::string_view what, double value) {
  if (!std::isfinite(value)) {
    throw InvalidInput(std::string(where) + ": " + std::string(what) + " must be finite (got " +
                       format_value(value) + ")");
  }
}

void require_poisson_ratio(std::string_view where, double nu) {
  if (!(nu >= 0.0 && nu < 0.5)) {
    throw InvalidInput(std::string(where) + ": Poisson's ratio nu must lie in [0, 0.5) (got " +
                       format_value(nu) + ")");
  }
}

void require_friction_coefficient(std::string_view where, double mu) {
  if (!(mu >= 0.0 && mu <= kMaxFrictionCoefficient)) {
    throw InvalidInput(std::string(where) + ": friction coefficient mu must lie in [0, " +
                       format_value(kMaxFrictionCoefficient) + "] (got " + format_value(mu) + ")");
  }
}

void require_in_half_space(std::string_view where, double z) {
  if (!(z >= 0.0) || !std::isfinite(z)) {
    throw InvalidInput(std::string(where) +
                       ": the point must lie in the body, depth z >= 0 and finite (got z = " +
                       format_value(z) + ")");
  }
}

}  // namespace cs::oracles

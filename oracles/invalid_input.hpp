#pragma once
// The error every oracle throws for input it cannot answer (a non-positive length, a Poisson's
// ratio outside [0, 0.5), a point outside the body, a load past an oracle's validity), and the
// precondition checks that throw it. Messages are one line and name the parameter and value,
// e.g. "hertz_plane_contact: radius R must be positive and finite (got -1)".

#include <stdexcept>
#include <string>
#include <string_view>

namespace cs::oracles {

/// Bad input to an oracle. Derives from std::invalid_argument so that callers which map
/// std::invalid_argument to a usage error (apps/main.cpp: exit code 2) need nothing more.
class InvalidInput : public std::invalid_argument {
 public:
  explicit InvalidInput(const std::string& what) : std::invalid_argument(what) {}
};

/// Shortest text that reads back as `value` ("0.25", "-1", "1e-300", "nan", "inf").
std::string format_value(double value);

/// Throws InvalidInput "<where>: <what> must be positive and finite (got <value>)" unless
/// 0 < value < inf.
void require_positive(std::string_view where, std::string_view what, double value);

/// Throws InvalidInput "<where>: <what> must be >= 0 and finite (got <value>)".
void require_non_negative(std::string_view where, std::string_view what, double value);

/// Throws InvalidInput unless `value` is finite.
void require_finite(std::string_view where, std::string_view what, double value);

/// Throws InvalidInput unless 0 <= nu < 0.5 (the range the study's fields are valid for:
/// nu = 0.5 makes the half-space incompressible, nu < 0 is excluded by the issue).
void require_poisson_ratio(std::string_view where, double nu);

/// The largest friction coefficient an oracle accepts: Coulomb coefficients of real pairs lie
/// below about 1.5; past 10 an input is a typo or a unit error, not a material.
inline constexpr double kMaxFrictionCoefficient = 10.0;

/// Throws InvalidInput unless 0 <= mu <= kMaxFrictionCoefficient (finite), e.g.
/// "<where>: friction coefficient mu must lie in [0, 10] (got 12)".
void require_friction_coefficient(std::string_view where, double mu);

/// Throws InvalidInput unless the depth z (pointing into the body) is finite and >= 0.
void require_in_half_space(std::string_view where, double z);

}  // namespace cs::oracles

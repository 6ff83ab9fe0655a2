// The GSL quadrature wrappers on integrals known in closed form, and their failure reports.

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "oracles/quadrature.hpp"
#include "support/tolerance.hpp"

namespace cs::oracles {
namespace {

using cs::testing::Near;
using std::numbers::pi;

// Requested 1e-12; allow 1e-11 for GSL's error estimate being an estimate.
constexpr cs::testing::Tolerance kQuadrature{.rel = 1e-11, .abs = 1e-13};
constexpr QuadratureTolerance kTol{.abs = 0.0, .rel = 1e-12};

TEST(Quadrature, EndPointInverseSquareRoot) {
  // int_0^1 x^(-1/2) dx = 2
  EXPECT_TRUE(Near(integrate([](double x) { return 1.0 / std::sqrt(x); }, 0.0, 1.0, kTol).value,
                   2.0, kQuadrature));
}

TEST(Quadrature, BreakpointsAtAKink) {
  // int_-1^2 |x| dx = 1/2 + 2
  const double points[] = {-1.0, 0.0, 2.0};
  EXPECT_TRUE(
      Near(integrate_with_breakpoints([](double x) { return std::abs(x); }, points, kTol).value,
           2.5, kQuadrature));
}

TEST(Quadrature, SemiInfinite) {
  // int_0^inf dx / (1 + x^2) = pi / 2
  EXPECT_TRUE(
      Near(integrate_to_infinity([](double x) { return 1.0 / (1.0 + x * x); }, 0.0, kTol).value,
           pi / 2.0, kQuadrature));
}

TEST(Quadrature, AlgebraicEndWeights) {
  // int_-1^1 (1 + x)^(-1/2) (1 - x)^(-1/2) dx = pi
  EXPECT_TRUE(
      Near(integrate_algebraic_ends([](double) { return 1.0; }, -1.0, 1.0, -0.5, -0.5, kTol).value,
           pi, kQuadrature));
}

TEST(Quadrature, CauchyPrincipalValueWithSingularEnds) {
  // PV int_-1^1 (1 - s^2)^(1/2) / (s - x) ds = -pi x, and PV int_-1^1 (1 - s^2)^(-1/2) /
  // (s - x) ds = 0, for |x| < 1 (the Hertz and flat-punch kernels). Zero results need an
  // absolute tolerance; QAGS reaches 1e-10, not 1e-12, next to an inverse square root.
  constexpr QuadratureTolerance kPvTol{.abs = 1e-12, .rel = 1e-12};
  constexpr QuadratureTolerance kPvTolEnds{.abs = 1e-10, .rel = 1e-10};
  for (const double x : {-0.7, 0.0, 0.3, 0.95}) {
    const auto hertz = integrate_cauchy_principal_value(
        [](double s) { return std::sqrt((1.0 - s) * (1.0 + s)); }, -1.0, 1.0, x, kPvTol);
    EXPECT_TRUE(Near(hertz.value, -pi * x, kQuadrature)) << x;
    const auto punch = integrate_cauchy_principal_value(
        [](double s) { return 1.0 / std::sqrt((1.0 - s) * (1.0 + s)); }, -1.0, 1.0, x, kPvTolEnds);
    EXPECT_TRUE(Near(punch.value, 0.0, {.rel = 0.0, .abs = 1e-9})) << x;
  }
}

TEST(Quadrature, FailuresThrowInsteadOfAborting) {
  // Not integrable: 1/x on (0, 1].
  EXPECT_THROW(integrate([](double x) { return 1.0 / x; }, 0.0, 1.0, kTol), QuadratureFailure);
  // Non-finite integrand.
  EXPECT_THROW(integrate([](double) { return std::nan(""); }, 0.0, 1.0, kTol), QuadratureFailure);
  // Pole outside the interval.
  EXPECT_THROW(integrate_cauchy_principal_value([](double) { return 1.0; }, 0.0, 1.0, 2.0, kTol),
               QuadratureFailure);
}

}  // namespace
}  // namespace cs::oracles

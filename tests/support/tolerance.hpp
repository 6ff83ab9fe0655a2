#pragma once
// The one tolerance helper of the test suites: |actual - expected| <= abs + rel * |expected|.
// Every caller states in a word why its tolerance is what it is.

#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace cs::testing {

/// An absolute plus relative tolerance.
struct Tolerance {
  double rel = 0.0;  ///< relative part, multiplied by |expected|
  double abs = 0.0;  ///< absolute floor, for expected values near zero
};

/// GoogleTest predicate: passes when |actual - expected| <= tol.abs + tol.rel * |expected|.
inline ::testing::AssertionResult Near(double actual, double expected, Tolerance tol) {
  const double allowed = tol.abs + tol.rel * std::abs(expected);
  const double diff = std::abs(actual - expected);
  if (std::isfinite(actual) && diff <= allowed) {
    return ::testing::AssertionSuccess();
  }
  std::ostringstream msg;
  msg.precision(17);
  msg << "actual " << actual << " vs expected " << expected << ": |diff| = " << diff
      << " > allowed " << allowed << " (rel " << tol.rel << ", abs " << tol.abs << ")";
  return ::testing::AssertionFailure() << msg.str();
}

}  // namespace cs::testing

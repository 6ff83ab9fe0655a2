#pragma once
// A power of two to measure lengths in, so that oracles evaluate scale-free: every length
// divided by it is at most 2 in magnitude, the division is exact (it only shifts exponents),
// and products of lengths neither overflow nor underflow until the answer itself does.

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace cs::oracles {

/// Lengths measured in the unit 2^exponent.
struct LengthScale {
  int exponent = 0;

  /// `length` in this unit (exact unless the result is subnormal).
  [[nodiscard]] double of(double length) const { return std::ldexp(length, -exponent); }
  /// `value` per unit length: value / 2^exponent.
  [[nodiscard]] double per_unit(double value) const { return std::ldexp(value, -exponent); }
};

/// The power of two at or below the largest |length| (all finite, one of them non-zero).
inline LengthScale length_scale(std::initializer_list<double> lengths) {
  double largest = 0.0;
  for (const double length : lengths)
    largest = std::max(largest, std::abs(length));
  return {largest > 0.0 ? std::ilogb(largest) : 0};
}

}  // namespace cs::oracles

#pragma once
// A command-line number check: CLI11's own ranges let NaN through (every comparison with it is
// false), read an empty value as 0, and print infinity as its 309 digits.

#include <cmath>

#include <CLI/CLI.hpp>

namespace cs::apps {

/// Accepts the whole text as one finite number, above `lo` (lo_open) or from `lo`, up to `hi`;
/// the message names the text and the range ("'nan' is not a finite number above 0").
CLI::Validator finite_number(double lo = -INFINITY, bool lo_open = false, double hi = INFINITY);

}  // namespace cs::apps

#pragma once
// The observed order of convergence: the least-squares slope of log|error| against log h
// over the meshes of one option set (cf. MFEM's tests/convergence: a rate, not a raw error).
// For the singular flat punch the same fit of log(value) against log h gives the (negative)
// rate at which the edge stress grows.

#include <optional>
#include <vector>

namespace cs::reports {

/// One point of a convergence plot.
struct SizePoint {
  double h = 0.0;  ///< element size at the contact (over a, or b)
  double y = 0.0;  ///< |error| in percent, or the value for a singular quantity
};

/// Least-squares slope of log(y) over log(h), using points with h > 0 and y > 0; nullopt
/// with fewer than two such points or when all h are equal.
std::optional<double> observed_order(const std::vector<SizePoint>& points);

}  // namespace cs::reports

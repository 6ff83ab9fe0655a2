#pragma once
// One-dimensional node spacings: the normalized node coordinates 0 = t_0 < t_1 < ... < t_n = 1
// along one axis of a structured block.

#include <vector>

namespace cs::solver {

/// How the nodes of one block axis are spaced.
enum class SpacingKind {
  Uniform,     ///< equal element sizes
  Geometric,   ///< successive element sizes grow by `ratio` (ratio < 1: they shrink)
  Breakpoints  ///< explicit normalized node coordinates (n + 1 of them, 0 first, 1 last)
};

/// The spacing of one block axis. `ratio` is used by Geometric, `breakpoints` by Breakpoints.
struct Spacing {
  SpacingKind kind = SpacingKind::Uniform;
  double ratio = 1.0;               ///< size of element i+1 over size of element i (> 0)
  std::vector<double> breakpoints;  ///< normalized node coordinates, strictly increasing
};

/// The n + 1 normalized node coordinates of `n` elements spaced as `spacing` says.
/// Throws MeshError on n < 1, a non-positive ratio, or breakpoints that are not n + 1 strictly
/// increasing values from 0 to 1. `what` prefixes the message (e.g. "make_block: x spacing").
std::vector<double> normalized_coordinates(const Spacing& spacing, int n, const char* what);

/// n equal elements on [0, 1].
std::vector<double> uniform_coordinates(int n);

/// n elements on [0, 1] whose sizes grow by `ratio` from one to the next (ratio > 0).
std::vector<double> geometric_coordinates(int n, double ratio);

// ---- Physical coordinates: graded and piecewise spacings ------------------------------------

/// How elements grow away from a refined point: first size, growth factor, largest size.
struct Grading {
  double h_min = 0.1;    ///< size of the element(s) at the refined point (> 0)
  double growth = 1.2;   ///< largest ratio of neighbouring element sizes (>= 1)
  double h_max = 1e300;  ///< sizes are capped here (>= h_min)
};

/// Node coordinates from x0 to x1 (x1 > x0) whose first element, at x0, has size grading.h_min
/// and whose sizes then grow by a common factor g <= grading.growth, capped at grading.h_max,
/// chosen so that the last node lands on x1 exactly. If [x0, x1] is shorter than what even
/// uniform h_min elements would fill, the elements are uniform and no smaller than h_min.
/// Throws MeshError on bad input.
std::vector<double> graded_from(double x0, double x1, const Grading& grading);

/// As graded_from, but refined at x1 (the sizes shrink toward x1).
std::vector<double> graded_to(double x0, double x1, const Grading& grading);

/// Node coordinates on [x0, x1] refined toward an interior point x_star (x0 <= x_star <= x1,
/// which is a node): graded_to(x0, x_star) followed by graded_from(x_star, x1).
std::vector<double> refined_toward(double x0, double x1, double x_star, const Grading& grading);

/// Concatenates coordinate lists end to start (each piece must start where the previous one
/// ends, up to round-off; the shared node appears once). Throws MeshError otherwise.
std::vector<double> join_coordinates(const std::vector<std::vector<double>>& pieces);

/// Uniform node coordinates from x0 to x1 with n elements.
std::vector<double> uniform_between(double x0, double x1, int n);

/// A Breakpoints spacing reproducing the physical coordinates (normalized to [0, 1]).
Spacing breakpoints_of(const std::vector<double>& coordinates);

}  // namespace cs::solver

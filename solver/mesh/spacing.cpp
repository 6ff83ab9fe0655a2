#include "solver/mesh/spacing.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {

std::vector<double> uniform_coordinates(int n) {
  if (n < 1) {
    throw MeshError(fmt::format("uniform_coordinates: n = {} (must be >= 1)", n));
  }
  std::vector<double> t(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    t[i] = static_cast<double>(i) / n;
  }
  t[n] = 1.0;
  return t;
}

std::vector<double> geometric_coordinates(int n, double ratio) {
  if (n < 1) {
    throw MeshError(fmt::format("geometric_coordinates: n = {} (must be >= 1)", n));
  }
  if (!(ratio > 0.0) || !std::isfinite(ratio)) {
    throw MeshError(fmt::format("geometric_coordinates: ratio = {} (must be > 0)", ratio));
  }
  std::vector<double> t(static_cast<std::size_t>(n) + 1, 0.0);
  double size = 1.0;
  for (int i = 1; i <= n; ++i) {
    t[i] = t[i - 1] + size;
    size *= ratio;
  }
  const double total = t[n];
  for (double& ti : t) {
    ti /= total;
  }
  t[n] = 1.0;
  return t;
}

std::vector<double> normalized_coordinates(const Spacing& spacing, int n, const char* what) {
  if (n < 1) {
    throw MeshError(fmt::format("{}: n = {} (must be >= 1)", what, n));
  }
  switch (spacing.kind) {
    case SpacingKind::Uniform:
      return uniform_coordinates(n);
    case SpacingKind::Geometric:
      if (!(spacing.ratio > 0.0) || !std::isfinite(spacing.ratio)) {
        throw MeshError(fmt::format("{}: geometric ratio = {} (must be > 0)", what, spacing.ratio));
      }
      return geometric_coordinates(n, spacing.ratio);
    case SpacingKind::Breakpoints: {
      const auto& b = spacing.breakpoints;
      if (static_cast<int>(b.size()) != n + 1) {
        throw MeshError(
            fmt::format("{}: {} breakpoints for {} elements (need {})", what, b.size(), n, n + 1));
      }
      constexpr double kEnds = 1e-12;  // round-off allowed at the ends, then snapped
      if (std::abs(b.front()) > kEnds || std::abs(b.back() - 1.0) > kEnds) {
        throw MeshError(fmt::format("{}: breakpoints run from {} to {} (must be 0 to 1)", what,
                                    b.front(), b.back()));
      }
      for (int i = 0; i < n; ++i) {
        if (!(b[i + 1] > b[i]) || !std::isfinite(b[i + 1])) {
          throw MeshError(
              fmt::format("{}: breakpoints not strictly increasing at index {}", what, i + 1));
        }
      }
      std::vector<double> t = b;
      t.front() = 0.0;
      t.back() = 1.0;
      return t;
    }
  }
  throw MeshError(fmt::format("{}: unknown spacing kind", what));
}

}  // namespace cs::solver

namespace cs::solver {
namespace {

void check_grading(const Grading& g, const char* what) {
  if (!(g.h_min > 0.0) || !std::isfinite(g.h_min)) {
    throw MeshError(fmt::format("{}: h_min = {} (must be > 0)", what, g.h_min));
  }
  if (!(g.growth >= 1.0) || !std::isfinite(g.growth)) {
    throw MeshError(fmt::format("{}: growth = {} (must be >= 1)", what, g.growth));
  }
  if (!(g.h_max >= g.h_min)) {
    throw MeshError(fmt::format("{}: h_max = {} < h_min = {}", what, g.h_max, g.h_min));
  }
}

/// Sum of n sizes min(h_min g^i, h_max), i = 0..n-1.
double graded_length(int n, double g, const Grading& grading) {
  double sum = 0.0;
  double h = grading.h_min;
  for (int i = 0; i < n; ++i) {
    sum += std::min(h, grading.h_max);
    h *= g;
  }
  return sum;
}

}  // namespace

std::vector<double> graded_from(double x0, double x1, const Grading& grading) {
  check_grading(grading, "graded_from");
  if (!(x1 > x0) || !std::isfinite(x0) || !std::isfinite(x1)) {
    throw MeshError(fmt::format("graded_from: interval [{}, {}] is empty", x0, x1));
  }
  const double length = x1 - x0;
  constexpr int kMaxElements = 10'000'000;
  // Fewest elements whose full-growth sizes reach x1.
  int n = 1;
  while (graded_length(n, grading.growth, grading) < length) {
    if (++n > kMaxElements) {
      throw MeshError(fmt::format("graded_from: more than {} elements needed", kMaxElements));
    }
  }
  if (n * grading.h_min >= length) {  // too short to grade: uniform, each >= h_min
    const int m = std::max(1, static_cast<int>(std::floor(length / grading.h_min * (1 + 1e-12))));
    return uniform_between(x0, x1, m);
  }
  // Bisection for the common growth g in [1, growth] with graded_length(n, g) = length.
  double lo = 1.0;
  double hi = grading.growth;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (graded_length(n, mid, grading) < length ? lo : hi) = mid;
  }
  const double g = 0.5 * (lo + hi);
  std::vector<double> x(static_cast<std::size_t>(n) + 1, x0);
  double h = grading.h_min;
  for (int i = 1; i <= n; ++i) {
    x[i] = x[i - 1] + std::min(h, grading.h_max);
    h *= g;
  }
  x[n] = x1;  // absorb the bisection's last-bit error in the largest element
  return x;
}

std::vector<double> graded_to(double x0, double x1, const Grading& grading) {
  std::vector<double> mirrored = graded_from(-x1, -x0, grading);
  std::vector<double> x(mirrored.rbegin(), mirrored.rend());
  for (double& xi : x)
    xi = -xi;
  x.front() = x0;
  x.back() = x1;
  return x;
}

std::vector<double> refined_toward(double x0, double x1, double x_star, const Grading& grading) {
  if (!(x_star >= x0 && x_star <= x1) || !(x1 > x0)) {
    throw MeshError(
        fmt::format("refined_toward: x* = {} is not in [{}, {}] (or it is empty)", x_star, x0, x1));
  }
  std::vector<std::vector<double>> pieces;
  if (x_star > x0)
    pieces.push_back(graded_to(x0, x_star, grading));
  if (x_star < x1)
    pieces.push_back(graded_from(x_star, x1, grading));
  return join_coordinates(pieces);
}

std::vector<double> join_coordinates(const std::vector<std::vector<double>>& pieces) {
  std::vector<double> x;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const auto& piece = pieces[p];
    if (piece.size() < 2) {
      throw MeshError(fmt::format("join_coordinates: piece {} has {} nodes", p, piece.size()));
    }
    for (std::size_t i = 1; i < piece.size(); ++i) {
      if (!(piece[i] > piece[i - 1])) {
        throw MeshError(
            fmt::format("join_coordinates: piece {} is not increasing at node {}", p, i));
      }
    }
    if (x.empty()) {
      x = piece;
      continue;
    }
    const double scale = std::max({1.0, std::abs(x.back()), std::abs(piece.front())});
    if (std::abs(piece.front() - x.back()) > 1e-12 * scale) {
      throw MeshError(
          fmt::format("join_coordinates: piece {} starts at {} but the previous ends "
                      "at {}",
                      p, piece.front(), x.back()));
    }
    x.insert(x.end(), piece.begin() + 1, piece.end());
  }
  return x;
}

std::vector<double> uniform_between(double x0, double x1, int n) {
  if (n < 1 || !(x1 > x0)) {
    throw MeshError(fmt::format("uniform_between: n = {} on [{}, {}]", n, x0, x1));
  }
  std::vector<double> x(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    x[i] = x0 + (x1 - x0) * static_cast<double>(i) / n;
  }
  x[n] = x1;
  return x;
}

Spacing breakpoints_of(const std::vector<double>& coordinates) {
  if (coordinates.size() < 2 || !(coordinates.back() > coordinates.front())) {
    throw MeshError("breakpoints_of: need at least two increasing coordinates");
  }
  Spacing spacing;
  spacing.kind = SpacingKind::Breakpoints;
  const double x0 = coordinates.front();
  const double length = coordinates.back() - x0;
  for (double x : coordinates)
    spacing.breakpoints.push_back((x - x0) / length);
  spacing.breakpoints.front() = 0.0;
  spacing.breakpoints.back() = 1.0;
  return spacing;
}

}  // namespace cs::solver

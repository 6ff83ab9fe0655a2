#pragma once
// Gauss-Legendre quadrature on [-1, 1] and its tensor product on the square [-1, 1]^2.

#include <vector>

#include <Eigen/Core>

namespace cs::solver {

/// An n-point Gauss-Legendre rule on [-1, 1]: exact for polynomials of degree 2n - 1.
struct GaussRule1D {
  std::vector<double> points;   ///< abscissae, increasing
  std::vector<double> weights;  ///< weights, summing to 2
  int size() const { return static_cast<int>(points.size()); }
};

/// The largest number of points per direction the rules support.
inline constexpr int kMaxGaussPoints = 16;

/// The n-point rule (1 <= n <= kMaxGaussPoints; throws std::invalid_argument otherwise).
/// Nodes are Newton-refined roots of the Legendre polynomial P_n, accurate to round-off.
const GaussRule1D& gauss_rule_1d(int n);

/// An n x n tensor-product rule on [-1, 1]^2. Point q = i + n j has natural coordinates
/// (xi_i, eta_j): xi runs fastest.
struct GaussRule2D {
  std::vector<Eigen::Vector2d> points;  ///< natural coordinates (xi, eta)
  std::vector<double> weights;          ///< weights, summing to 4
  int points_per_direction = 0;
  int size() const { return static_cast<int>(points.size()); }
};

/// The n x n rule (1 <= n <= kMaxGaussPoints).
const GaussRule2D& gauss_rule_2d(int n);

}  // namespace cs::solver

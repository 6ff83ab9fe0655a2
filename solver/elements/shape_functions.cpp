#include "solver/elements/shape_functions.hpp"

#include <stdexcept>
#include <string>

namespace cs::solver {
namespace {

constexpr double kCornerXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kCornerEta[4] = {-1.0, -1.0, 1.0, 1.0};
constexpr double kMidXi[4] = {0.0, 1.0, 0.0, -1.0};
constexpr double kMidEta[4] = {-1.0, 0.0, 1.0, 0.0};

void q4(const Eigen::Vector2d& p, ShapeValues& s) {
  const double xi = p.x();
  const double eta = p.y();
  for (int a = 0; a < 4; ++a) {
    const double xa = kCornerXi[a];
    const double ea = kCornerEta[a];
    s.N(a) = 0.25 * (1.0 + xi * xa) * (1.0 + eta * ea);
    s.dN_dxi(a, 0) = 0.25 * xa * (1.0 + eta * ea);
    s.dN_dxi(a, 1) = 0.25 * ea * (1.0 + xi * xa);
  }
}

void q8(const Eigen::Vector2d& p, ShapeValues& s) {
  const double xi = p.x();
  const double eta = p.y();
  for (int a = 0; a < 4; ++a) {
    const double xa = kCornerXi[a];
    const double ea = kCornerEta[a];
    const double fx = 1.0 + xi * xa;
    const double fe = 1.0 + eta * ea;
    const double g = xi * xa + eta * ea - 1.0;
    s.N(a) = 0.25 * fx * fe * g;
    s.dN_dxi(a, 0) = 0.25 * xa * fe * (g + fx);
    s.dN_dxi(a, 1) = 0.25 * ea * fx * (g + fe);
  }
  for (int m = 0; m < 4; ++m) {
    const int a = 4 + m;
    const double xa = kMidXi[m];
    const double ea = kMidEta[m];
    if (xa == 0.0) {
      s.N(a) = 0.5 * (1.0 - xi * xi) * (1.0 + eta * ea);
      s.dN_dxi(a, 0) = -xi * (1.0 + eta * ea);
      s.dN_dxi(a, 1) = 0.5 * ea * (1.0 - xi * xi);
    } else {
      s.N(a) = 0.5 * (1.0 + xi * xa) * (1.0 - eta * eta);
      s.dN_dxi(a, 0) = 0.5 * xa * (1.0 - eta * eta);
      s.dN_dxi(a, 1) = -eta * (1.0 + xi * xa);
    }
  }
}

}  // namespace

ShapeValues shape_functions(ElementType type, const Eigen::Vector2d& xi) {
  ShapeValues s;
  s.N.setZero();
  s.dN_dxi.setZero();
  if (type == ElementType::Q4) {
    s.n = 4;
    q4(xi, s);
  } else {
    s.n = 8;
    q8(xi, s);
  }
  return s;
}

Eigen::Vector2d node_natural_coordinates(ElementType type, int a) {
  if (a < 0 || a >= nodes_per_element(type)) {
    throw std::out_of_range("node_natural_coordinates: local node " + std::to_string(a));
  }
  if (a < 4)
    return {kCornerXi[a], kCornerEta[a]};
  return {kMidXi[a - 4], kMidEta[a - 4]};
}

Eigen::Vector2d side_point_natural_coordinates(int side, double t) {
  switch (side) {
    case 0:
      return {t, -1.0};
    case 1:
      return {1.0, t};
    case 2:
      return {-t, 1.0};
    case 3:
      return {-1.0, -t};
    default:
      throw std::out_of_range("side_point_natural_coordinates: side " + std::to_string(side));
  }
}

SideShapeValues side_shape_functions(ElementType type, double t) {
  SideShapeValues s;
  if (type == ElementType::Q4) {
    s.n = 2;
    s.N = {0.5 * (1.0 - t), 0.5 * (1.0 + t), 0.0};
    s.dN = {-0.5, 0.5, 0.0};
  } else {
    s.n = 3;
    s.N = {0.5 * t * (t - 1.0), 0.5 * t * (t + 1.0), 1.0 - t * t};
    s.dN = {t - 0.5, t + 0.5, -2.0 * t};
  }
  return s;
}

}  // namespace cs::solver

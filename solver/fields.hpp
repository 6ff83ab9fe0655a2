#pragma once
// Fields given as plain callables of position: prescribed displacements, tractions, body forces.

#include <functional>

#include <Eigen/Core>

namespace cs::solver {

/// A scalar function of position (x|r, z), e.g. a prescribed displacement component.
using ScalarField = std::function<double(const Eigen::Vector2d& position)>;

/// A vector function of position (x|r, z), e.g. a traction or a body force.
using VectorField = std::function<Eigen::Vector2d(const Eigen::Vector2d& position)>;

/// The constant scalar field `value`.
inline ScalarField constant_field(double value) {
  return [value](const Eigen::Vector2d&) { return value; };
}

/// The constant vector field `value`.
inline VectorField constant_field(const Eigen::Vector2d& value) {
  return [value](const Eigen::Vector2d&) { return value; };
}

}  // namespace cs::solver

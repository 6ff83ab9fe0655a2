#include "solver/mesh/far_field_stretch.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "solver/mesh/mesh_error.hpp"

namespace cs::solver {
namespace {

void require_valid(const FarFieldStretch& s) {
  const bool finite =
      std::isfinite(s.inner) && std::isfinite(s.outer) && std::isfinite(s.new_outer);
  if (!finite || !(s.inner > 0.0) || !(s.outer > s.inner) || !(s.new_outer >= s.outer)) {
    throw MeshError(
        fmt::format("far-field stretch: need 0 < inner < outer <= new outer (inner {}, outer {}, "
                    "new outer {})",
                    s.inner, s.outer, s.new_outer));
  }
}

double exponent(const FarFieldStretch& s) {
  return std::log(s.new_outer / s.inner) / std::log(s.outer / s.inner);
}

}  // namespace

Eigen::Vector2d far_field_stretch(const FarFieldStretch& s, const Eigen::Vector2d& p) {
  require_valid(s);
  const double r = std::max(std::abs(p.x()), std::abs(p.y()));
  if (r <= s.inner)
    return p;
  const double rho = s.inner * std::pow(r / s.inner, exponent(s));
  return p * (rho / r);
}

void stretch_far_field(Mesh& mesh, const FarFieldStretch& s) {
  require_valid(s);
  if (s.new_outer == s.outer)
    return;
  const std::vector<Eigen::Vector2d> before = mesh.nodes;
  std::vector<char> is_corner(mesh.nodes.size(), 0);
  for (const auto& e : mesh.elements) {
    for (int c = 0; c < 4; ++c)
      is_corner[e[c]] = 1;
  }
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (is_corner[n])
      mesh.nodes[n] = far_field_stretch(s, before[n]);
  }
  if (mesh.type != ElementType::Q8)
    return;
  for (const auto& e : mesh.elements) {
    for (int side = 0; side < 4; ++side)
      mesh.nodes[e[4 + side]] = 0.5 * (mesh.nodes[e[side]] + mesh.nodes[e[(side + 1) % 4]]);
  }
}

}  // namespace cs::solver

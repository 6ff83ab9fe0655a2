#include "solver/mesh/circular_sector.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <fmt/format.h>

#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/mesh_weld.hpp"
#include "solver/mesh/spacing.hpp"
#include "solver/mesh/structured_block.hpp"

namespace cs::solver {
namespace {

using Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

Vector2d on_circle(double radius, double theta) {
  return {radius * std::cos(theta), radius * std::sin(theta)};
}

/// Names edge set `name` (and its node set) the boundary sides whose nodes satisfy `on`.
void name_boundary(Mesh& mesh, const std::string& name,
                   const std::function<bool(const Vector2d&)>& on) {
  mesh.edge_sets[name] = boundary_sides_where(mesh, on);
  if (mesh.edge_sets[name].empty())
    throw MeshError(fmt::format("circular sector: no boundary side on '{}'", name));
  set_node_set_from_edge_set(mesh, name);
}

/// Predicates of the straight and curved boundaries, to `tolerance`.
std::function<bool(const Vector2d&)> on_radius(double radius, double tolerance) {
  return [=](const Vector2d& x) { return std::abs(x.norm() - radius) < tolerance; };
}
std::function<bool(const Vector2d&)> on_x_axis(double tolerance) {
  return [=](const Vector2d& x) { return std::abs(x.y()) < tolerance; };
}
std::function<bool(const Vector2d&)> on_z_axis(double tolerance) {
  return [=](const Vector2d& x) { return std::abs(x.x()) < tolerance; };
}

}  // namespace

int square_radial_count(double inner_radius, double outer_radius, int n_arc) {
  if (!(inner_radius > 0.0) || !(outer_radius > inner_radius) || n_arc < 1)
    throw MeshError(fmt::format("square_radial_count: radii {} < {} and n_arc {} >= 1 needed",
                                inner_radius, outer_radius, n_arc));
  const double growth = 1.0 + kPi / (2.0 * n_arc);
  const int n =
      static_cast<int>(std::ceil(std::log(outer_radius / inner_radius) / std::log(growth) - 1e-9));
  return std::max(2, n);
}

Mesh make_quarter_annulus(const QuarterAnnulusSpec& spec) {
  const double ri = spec.inner_radius, ro = spec.outer_radius;
  if (!(ri > 0.0) || !(ro > ri) || !std::isfinite(ro))
    throw MeshError(
        fmt::format("make_quarter_annulus: radii {} and {} (need 0 < ri < ro)", ri, ro));
  if (spec.n_arc < 1 || spec.n_radial < 1)
    throw MeshError(fmt::format("make_quarter_annulus: n_arc = {}, n_radial = {} (must be >= 1)",
                                spec.n_arc, spec.n_radial));
  MappedBlockSpec block;
  block.type = spec.type;
  block.body_name = spec.body_name;
  block.v = uniform_coordinates(spec.n_arc);
  // Geometric radii, normalized to u in [0, 1]: r(u) is linear in u between the node radii.
  for (int i = 0; i <= spec.n_radial; ++i) {
    const double r = ri * std::pow(ro / ri, static_cast<double>(i) / spec.n_radial);
    block.u.push_back(i == spec.n_radial ? 1.0 : (r - ri) / (ro - ri));
  }
  block.u.front() = 0.0;
  block.map = [ri, ro](double u, double v) { return on_circle(ri + u * (ro - ri), v * kPi / 2); };
  Mesh mesh = make_mapped_block(block);
  mesh.edge_sets.clear();
  mesh.node_sets.clear();
  const double tol = 1e-9 * ro;
  name_boundary(mesh, "inner", on_radius(ri, tol));
  name_boundary(mesh, "outer", on_radius(ro, tol));
  name_boundary(mesh, "x_axis", on_x_axis(tol));
  name_boundary(mesh, "z_axis", on_z_axis(tol));
  rebuild_edge_node_sets(mesh);
  return mesh;
}

Mesh make_quarter_disc(const QuarterDiscSpec& spec) {
  const double R = spec.radius, s = spec.core_fraction * spec.radius;
  if (!(R > 0.0) || !std::isfinite(R))
    throw MeshError(fmt::format("make_quarter_disc: radius {} (must be > 0)", R));
  if (spec.n_arc < 2 || spec.n_arc % 2 != 0 || spec.n_radial < 1)
    throw MeshError(fmt::format("make_quarter_disc: n_arc = {} (even, >= 2), n_radial = {} (>= 1)",
                                spec.n_arc, spec.n_radial));
  if (!(spec.core_fraction > 0.0) || !(spec.core_fraction < std::numbers::sqrt2 / 2))
    throw MeshError(fmt::format("make_quarter_disc: core fraction {} (must be in (0, 1/sqrt 2))",
                                spec.core_fraction));
  const int n = spec.n_arc / 2;
  MappedBlockSpec core;
  core.type = spec.type;
  core.u = core.v = uniform_coordinates(n);
  core.map = [s](double u, double v) { return Vector2d(s * u, s * v); };
  // The curved blocks: u from the core's side (u = 0) out to the arc (u = 1), v along the arc.
  MappedBlockSpec lower = core, upper = core;
  lower.u = upper.u = uniform_coordinates(spec.n_radial);
  lower.map = [s, R](double u, double v) {
    return Vector2d((1 - u) * Vector2d(s, s * v) + u * on_circle(R, v * kPi / 4));
  };
  upper.map = [s, R](double u, double v) {
    return Vector2d((1 - u) * Vector2d(s * (1 - v), s) + u * on_circle(R, (1 + v) * kPi / 4));
  };
  Mesh mesh =
      weld_blocks({make_mapped_block(core), make_mapped_block(lower), make_mapped_block(upper)},
                  spec.body_name, 1e-9 * R);
  const double tol = 1e-9 * R;
  name_boundary(mesh, "arc", on_radius(R, tol));
  name_boundary(mesh, "x_axis", on_x_axis(tol));
  name_boundary(mesh, "z_axis", on_z_axis(tol));
  rebuild_edge_node_sets(mesh);
  return mesh;
}

}  // namespace cs::solver

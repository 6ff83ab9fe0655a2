#include "solver/mesh/indenter.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/mesh_transform.hpp"
#include "solver/mesh/structured_block.hpp"

namespace cs::solver {
namespace {

void check_positive(double value, const char* what, const char* where) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw MeshError(fmt::format("{}: {} = {} (must be > 0)", where, what, value));
  }
}

}  // namespace

IndenterProfile flat_profile(double half_width) {
  check_positive(half_width, "half_width", "flat_profile");
  return {[](double) { return 0.0; }, half_width, fmt::format("flat, half-width {}", half_width)};
}

IndenterProfile circle_profile(double radius, double half_width) {
  check_positive(radius, "radius", "circle_profile");
  check_positive(half_width, "half_width", "circle_profile");
  if (half_width > radius) {
    throw MeshError(
        fmt::format("circle_profile: half_width = {} exceeds radius = {}", half_width, radius));
  }
  return {[radius](double x) {
            // R - sqrt(R^2 - x^2) written without cancellation for x << R.
            return -x * x / (radius + std::sqrt(std::max(0.0, radius * radius - x * x)));
          },
          half_width, fmt::format("circle R = {}, half-width {}", radius, half_width)};
}

IndenterProfile rounded_punch_profile(double b, double r_e) {
  check_positive(b, "b", "rounded_punch_profile");
  check_positive(r_e, "r_e", "rounded_punch_profile");
  return {[b, r_e](double x) {
            if (x <= b)
              return 0.0;
            const double d = std::min(x - b, r_e);
            return -d * d / (r_e + std::sqrt(std::max(0.0, r_e * r_e - d * d)));
          },
          b + r_e, fmt::format("rounded punch b = {}, r_e = {}", b, r_e)};
}

namespace {

/// The point of the profile nearest to m with x in [x0, x1] (golden-section search on x).
Eigen::Vector2d nearest_on_profile(const IndenterProfile& profile, const Eigen::Vector2d& m,
                                   double x0, double x1) {
  auto dist2 = [&](double x) { return (Eigen::Vector2d(x, profile.z_of_x(x)) - m).squaredNorm(); };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = x0, hi = x1;
  double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
    if (dist2(c) < dist2(d)) {
      hi = d;
    } else {
      lo = c;
    }
    c = hi - g * (hi - lo);
    d = lo + g * (hi - lo);
  }
  const double x = 0.5 * (lo + hi);
  return {x, profile.z_of_x(x)};
}

}  // namespace

void wrap_onto_profile(Mesh& mesh, const IndenterProfile& profile, double height) {
  check_positive(height, "height", "wrap_onto_profile");
  if (!profile.z_of_x) {
    throw MeshError("wrap_onto_profile: the profile has no function");
  }
  std::vector<bool> corner(mesh.nodes.size(), mesh.type == ElementType::Q4);
  for (const auto& e : mesh.elements) {
    for (int c = 0; c < 4; ++c)
      corner[e[c]] = true;
  }
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (!corner[n])
      continue;
    auto& p = mesh.nodes[n];
    const double x = std::clamp(p.x(), 0.0, profile.half_width);
    const double drop = profile.z_of_x(x);
    if (!std::isfinite(drop) || !(drop > -height)) {
      throw MeshError(
          fmt::format("wrap_onto_profile: profile z = {} at x = {} is not above the "
                      "back face z = -{}",
                      drop, x, height));
    }
    p.y() += drop * (1.0 + p.y() / height);
  }
  if (mesh.type == ElementType::Q4)
    return;
  // Q8: straight sides inside, and on the contact surface mid-side nodes on the profile.
  for (const auto& e : mesh.elements) {
    for (int s = 0; s < 4; ++s) {
      mesh.nodes[e[4 + s]] = 0.5 * (mesh.nodes[e[s]] + mesh.nodes[e[(s + 1) % 4]]);
    }
  }
  const auto it = mesh.edge_sets.find("contact");
  if (it == mesh.edge_sets.end()) {
    throw MeshError("wrap_onto_profile: a Q8 indenter needs its edge set 'contact'");
  }
  for (const auto& side : it->second) {
    const auto n = mesh.side_nodes(side);
    const Eigen::Vector2d& p = mesh.nodes[n[0]];
    const Eigen::Vector2d& q = mesh.nodes[n[1]];
    const double x0 = std::min(p.x(), q.x());
    const double x1 = std::max(p.x(), q.x());
    const double xm = 0.5 * (x0 + x1);
    // Where the surface is gentle, straight below the x-midpoint (so mid-side nodes keep the x
    // of the indented body's); where it is steep, the profile point nearest the chord midpoint
    // (so the side stays close to straight and det J > 0).
    constexpr double kGentleSlope = 0.5;
    if (std::abs(q.y() - p.y()) <= kGentleSlope * (x1 - x0)) {
      mesh.nodes[n[2]] = {xm, profile.z_of_x(std::clamp(xm, 0.0, profile.half_width))};
    } else {
      mesh.nodes[n[2]] = nearest_on_profile(profile, 0.5 * (p + q), x0, x1);
    }
  }
}

void name_indenter_sets(Mesh& mesh) {
  rename_set(mesh, "top", "contact");
  rename_set(mesh, "bottom", "back");
}

Mesh make_indenter(const IndenterSpec& spec) {
  const auto& xs = spec.surface_x;
  check_positive(spec.profile.half_width, "profile half_width", "make_indenter");
  check_positive(spec.height, "height", "make_indenter");
  if (xs.size() < 2) {
    throw MeshError(fmt::format("make_indenter: {} surface x positions (need >= 2)", xs.size()));
  }
  const double w = spec.profile.half_width;
  if (std::abs(xs.front()) > 1e-12 * w || std::abs(xs.back() - w) > 1e-12 * w) {
    throw MeshError(fmt::format(
        "make_indenter: surface x positions run from {} to {} (must be 0 to half_width {})",
        xs.front(), xs.back(), w));
  }
  check_positive(spec.row_growth, "row_growth", "make_indenter");
  if (spec.n_rows < 1) {
    throw MeshError(fmt::format("make_indenter: n_rows = {} (must be >= 1)", spec.n_rows));
  }
  BlockSpec block;
  block.type = ElementType::Q4;
  block.origin = {0.0, -spec.height};
  block.size = {w, spec.height};
  block.nx = static_cast<int>(xs.size()) - 1;
  block.nz = spec.n_rows;
  block.x_spacing = breakpoints_of(xs);
  // Rows shrink toward the contact surface (z = 0 is the block's top).
  block.z_spacing = {SpacingKind::Geometric, 1.0 / spec.row_growth, {}};
  block.body_name = spec.body_name;
  Mesh mesh = make_block(block);
  // Columns exactly at the requested x (normalizing and scaling back may round the last bit).
  for (auto& p : mesh.nodes) {
    const auto it = std::lower_bound(xs.begin(), xs.end(), p.x());
    const auto nearest =
        (it == xs.end() || (it != xs.begin() && p.x() - *(it - 1) < *it - p.x())) ? it - 1 : it;
    p.x() = *nearest;
  }
  name_indenter_sets(mesh);
  if (spec.type == ElementType::Q8)
    mesh = to_quadratic(mesh);
  wrap_onto_profile(mesh, spec.profile, spec.height);
  return mesh;
}

}  // namespace cs::solver

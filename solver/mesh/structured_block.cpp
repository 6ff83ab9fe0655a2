#include "solver/mesh/structured_block.hpp"

#include <cmath>

#include <fmt/format.h>

namespace cs::solver {
namespace {

void check_coordinates(const std::vector<double>& t, const char* axis) {
  if (t.size() < 2) {
    throw MeshError(
        fmt::format("make_mapped_block: {} has {} node coordinates (need >= 2)", axis, t.size()));
  }
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (!(t[i] > t[i - 1]) || !std::isfinite(t[i])) {
      throw MeshError(fmt::format(
          "make_mapped_block: {} node coordinates not strictly increasing at index {}", axis, i));
    }
  }
}

/// Twice the signed area of the corner quadrilateral, split at each corner: the corner
/// Jacobian determinants of a bilinear element are the cross products of its adjacent edges.
double min_corner_cross(const Mesh& mesh, const std::array<int, 8>& e) {
  double least = INFINITY;
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d& p = mesh.nodes[e[c]];
    const Eigen::Vector2d a = mesh.nodes[e[(c + 1) % 4]] - p;
    const Eigen::Vector2d b = mesh.nodes[e[(c + 3) % 4]] - p;
    least = std::min(least, a.x() * b.y() - a.y() * b.x());
  }
  return least;
}

}  // namespace

Mesh make_mapped_block(const MappedBlockSpec& spec) {
  check_coordinates(spec.u, "u");
  check_coordinates(spec.v, "v");
  if (!spec.map) {
    throw MeshError("make_mapped_block: no map given");
  }
  const bool q8 = spec.type == ElementType::Q8;
  const int nu = static_cast<int>(spec.u.size()) - 1;
  const int nv = static_cast<int>(spec.v.size()) - 1;
  // The fine grid: corners at even indices, Q8 mid-sides at odd ones (element centers unused).
  const int step = q8 ? 2 : 1;
  const int fu = step * nu + 1;
  const int fv = step * nv + 1;
  auto fine_u = [&](int i) {
    return i % step == 0 ? spec.u[i / step] : 0.5 * (spec.u[i / 2] + spec.u[i / 2 + 1]);
  };
  auto fine_v = [&](int k) {
    return k % step == 0 ? spec.v[k / step] : 0.5 * (spec.v[k / 2] + spec.v[k / 2 + 1]);
  };

  Mesh mesh;
  mesh.type = spec.type;
  mesh.body_names = {spec.body_name};
  std::vector<int> id(static_cast<std::size_t>(fu) * fv, -1);
  auto at = [&](int i, int k) -> int& { return id[static_cast<std::size_t>(k) * fu + i]; };
  for (int k = 0; k < fv; ++k) {
    for (int i = 0; i < fu; ++i) {
      if (q8 && i % 2 == 1 && k % 2 == 1) {
        continue;  // element center: not a serendipity node
      }
      const Eigen::Vector2d p = spec.map(fine_u(i), fine_v(k));
      if (!p.allFinite()) {
        throw MeshError(
            fmt::format("make_mapped_block: map gives a non-finite point at u = {}, v = {}",
                        fine_u(i), fine_v(k)));
      }
      at(i, k) = mesh.n_nodes();
      mesh.nodes.push_back(p);
    }
  }

  mesh.elements.reserve(static_cast<std::size_t>(nu) * nv);
  for (int k = 0; k < nv; ++k) {
    for (int i = 0; i < nu; ++i) {
      const int i0 = step * i;
      const int k0 = step * k;
      std::array<int, 8> e;
      e.fill(-1);
      e[0] = at(i0, k0);
      e[1] = at(i0 + step, k0);
      e[2] = at(i0 + step, k0 + step);
      e[3] = at(i0, k0 + step);
      if (q8) {
        e[4] = at(i0 + 1, k0);
        e[5] = at(i0 + 2, k0 + 1);
        e[6] = at(i0 + 1, k0 + 2);
        e[7] = at(i0, k0 + 1);
      }
      const int index = mesh.n_elements();
      mesh.elements.push_back(e);
      if (!(min_corner_cross(mesh, e) > 0.0)) {
        throw MeshError(fmt::format(
            "make_mapped_block: element {} (u-column {}, v-row {}) is degenerate or inverted",
            index, i, k));
      }
    }
  }
  mesh.element_body.assign(mesh.elements.size(), 0);

  auto& nodes_bottom = mesh.node_sets["bottom"];
  auto& nodes_top = mesh.node_sets["top"];
  for (int i = 0; i < fu; ++i) {
    nodes_bottom.push_back(at(i, 0));
    nodes_top.push_back(at(i, fv - 1));
  }
  auto& nodes_left = mesh.node_sets["left"];
  auto& nodes_right = mesh.node_sets["right"];
  for (int k = 0; k < fv; ++k) {
    nodes_left.push_back(at(0, k));
    nodes_right.push_back(at(fu - 1, k));
  }
  auto& all = mesh.node_sets["all"];
  all.resize(mesh.nodes.size());
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    all[n] = n;
  }

  auto& edges_bottom = mesh.edge_sets["bottom"];
  auto& edges_top = mesh.edge_sets["top"];
  for (int i = 0; i < nu; ++i) {
    edges_bottom.push_back({i, 0});
    edges_top.push_back({(nv - 1) * nu + i, 2});
  }
  auto& edges_left = mesh.edge_sets["left"];
  auto& edges_right = mesh.edge_sets["right"];
  for (int k = 0; k < nv; ++k) {
    edges_left.push_back({k * nu, 3});
    edges_right.push_back({k * nu + nu - 1, 1});
  }
  return mesh;
}

Mesh make_block(const BlockSpec& spec) {
  if (!(spec.size.x() > 0.0) || !(spec.size.y() > 0.0) || !spec.size.allFinite()) {
    throw MeshError(fmt::format("make_block: size = ({}, {}) (both must be > 0)", spec.size.x(),
                                spec.size.y()));
  }
  if (!spec.origin.allFinite()) {
    throw MeshError("make_block: origin is not finite");
  }
  if (spec.nx < 1 || spec.nz < 1) {
    throw MeshError(
        fmt::format("make_block: nx = {}, nz = {} (both must be >= 1)", spec.nx, spec.nz));
  }
  MappedBlockSpec mapped;
  mapped.type = spec.type;
  mapped.u = normalized_coordinates(spec.x_spacing, spec.nx, "make_block: x spacing");
  mapped.v = normalized_coordinates(spec.z_spacing, spec.nz, "make_block: z spacing");
  const Eigen::Vector2d origin = spec.origin;
  const Eigen::Vector2d size = spec.size;
  mapped.map = [origin, size](double u, double v) {
    return Eigen::Vector2d(origin.x() + u * size.x(), origin.y() + v * size.y());
  };
  mapped.body_name = spec.body_name;
  Mesh mesh = make_mapped_block(mapped);
  // Exact edge coordinates (no round-off from u * size at the far edges).
  for (int n : mesh.node_sets.at("right"))
    mesh.nodes[n].x() = origin.x() + size.x();
  for (int n : mesh.node_sets.at("top"))
    mesh.nodes[n].y() = origin.y() + size.y();
  return mesh;
}

}  // namespace cs::solver

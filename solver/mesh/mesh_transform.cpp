#include "solver/mesh/mesh_transform.hpp"

#include <map>
#include <tuple>

#include <fmt/format.h>

#include "solver/mesh/mesh_sets.hpp"

namespace cs::solver {

Mesh refine_uniformly(const Mesh& mesh, int k) {
  if (mesh.type != ElementType::Q4) {
    throw MeshError("refine_uniformly: needs a Q4 mesh (refine first, then call to_quadratic)");
  }
  if (k < 1) {
    throw MeshError(fmt::format("refine_uniformly: k = {} (must be >= 1)", k));
  }
  if (k == 1) {
    return mesh;
  }
  Mesh fine;
  fine.type = ElementType::Q4;
  fine.body_names = mesh.body_names;
  fine.nodes = mesh.nodes;
  // Nodes inside an old side, keyed by (lower corner, higher corner, steps from the lower one).
  std::map<std::tuple<int, int, int>, int> side_nodes;
  auto edge_node = [&](int a, int b, int m) {  // node m/k of the way from corner a to corner b
    if (m == 0)
      return a;
    if (m == k)
      return b;
    const auto key = a < b ? std::make_tuple(a, b, m) : std::make_tuple(b, a, k - m);
    const auto it = side_nodes.find(key);
    if (it != side_nodes.end())
      return it->second;
    const double t = static_cast<double>(m) / k;
    const int id = fine.n_nodes();
    fine.nodes.push_back((1 - t) * mesh.nodes[a] + t * mesh.nodes[b]);
    side_nodes.emplace(key, id);
    return id;
  };
  fine.elements.reserve(mesh.elements.size() * k * k);
  std::vector<int> grid(static_cast<std::size_t>(k + 1) * (k + 1));
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const auto& c = mesh.elements[e];
    auto at = [&](int i, int j) -> int& { return grid[static_cast<std::size_t>(j) * (k + 1) + i]; };
    for (int m = 0; m <= k; ++m) {
      at(m, 0) = edge_node(c[0], c[1], m);
      at(k, m) = edge_node(c[1], c[2], m);
      at(k - m, k) = edge_node(c[2], c[3], m);
      at(0, k - m) = edge_node(c[3], c[0], m);
    }
    for (int j = 1; j < k; ++j) {
      for (int i = 1; i < k; ++i) {
        const double s = static_cast<double>(i) / k;
        const double t = static_cast<double>(j) / k;
        at(i, j) = fine.n_nodes();
        fine.nodes.push_back((1 - s) * (1 - t) * mesh.nodes[c[0]] + s * (1 - t) * mesh.nodes[c[1]] +
                             s * t * mesh.nodes[c[2]] + (1 - s) * t * mesh.nodes[c[3]]);
      }
    }
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < k; ++i) {
        std::array<int, 8> child;
        child.fill(-1);
        child[0] = at(i, j);
        child[1] = at(i + 1, j);
        child[2] = at(i + 1, j + 1);
        child[3] = at(i, j + 1);
        fine.elements.push_back(child);
        fine.element_body.push_back(mesh.element_body[e]);
      }
    }
  }
  const int kk = k * k;
  for (const auto& [name, sides] : mesh.edge_sets) {
    auto& out = fine.edge_sets[name];
    for (const auto& s : sides) {
      const int base = s.element * kk;
      for (int m = 0; m < k; ++m) {
        switch (s.side) {
          case 0:
            out.push_back({base + m, 0});
            break;
          case 1:
            out.push_back({base + m * k + (k - 1), 1});
            break;
          case 2:
            out.push_back({base + (k - 1) * k + (k - 1 - m), 2});
            break;
          default:
            out.push_back({base + (k - 1 - m) * k, 3});
            break;
        }
      }
    }
    sort_edge_set(fine, out);
  }
  fine.node_sets = mesh.node_sets;
  rebuild_edge_node_sets(fine);
  return fine;
}

Mesh to_quadratic(const Mesh& mesh) {
  if (mesh.type != ElementType::Q4) {
    throw MeshError("to_quadratic: the mesh is already Q8");
  }
  Mesh q8 = mesh;
  q8.type = ElementType::Q8;
  std::map<std::pair<int, int>, int> mid;
  for (auto& e : q8.elements) {
    for (int s = 0; s < 4; ++s) {
      const int a = e[s];
      const int b = e[(s + 1) % 4];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it == mid.end()) {
        it = mid.emplace(key, q8.n_nodes()).first;
        q8.nodes.push_back(0.5 * (q8.nodes[a] + q8.nodes[b]));
      }
      e[4 + s] = it->second;
    }
  }
  rebuild_edge_node_sets(q8);
  return q8;
}

void map_nodes(Mesh& mesh, const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& map) {
  for (auto& p : mesh.nodes) {
    p = map(p);
  }
}

void mirror_z(Mesh& mesh) {
  for (auto& p : mesh.nodes) {
    p.y() = -p.y();
  }
  // New order (0, 3, 2, 1): new side s is old side 3 - s; mid-side nodes follow their sides.
  for (auto& e : mesh.elements) {
    std::swap(e[1], e[3]);
    if (mesh.type == ElementType::Q8) {
      std::swap(e[4], e[7]);
      std::swap(e[5], e[6]);
    }
  }
  for (auto& [name, sides] : mesh.edge_sets) {
    for (auto& s : sides) {
      s.side = 3 - s.side;
    }
  }
}

}  // namespace cs::solver

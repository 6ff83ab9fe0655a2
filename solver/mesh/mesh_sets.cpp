#include "solver/mesh/mesh_sets.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include <fmt/format.h>

namespace cs::solver {
namespace {

template <class Map>
std::string known_names(const Map& sets) {
  std::string names;
  for (const auto& [name, unused] : sets) {
    names += (names.empty() ? "" : ", ") + name;
  }
  return names.empty() ? "none" : names;
}

Eigen::Vector2d side_midpoint(const Mesh& mesh, const ElementSide& s) {
  const auto n = mesh.side_nodes(s);
  return 0.5 * (mesh.nodes[n[0]] + mesh.nodes[n[1]]);
}

/// True when points spread at least as much in x as in z.
bool spreads_along_x(const std::vector<Eigen::Vector2d>& points) {
  if (points.empty()) {
    return true;
  }
  Eigen::Vector2d lo = points.front();
  Eigen::Vector2d hi = points.front();
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return hi.x() - lo.x() >= hi.y() - lo.y();
}

bool less_along(const Eigen::Vector2d& p, const Eigen::Vector2d& q, bool along_x) {
  return along_x ? (p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()))
                 : (p.y() < q.y() || (p.y() == q.y() && p.x() < q.x()));
}

}  // namespace

const std::vector<int>& node_set(const Mesh& mesh, const std::string& name) {
  const auto it = mesh.node_sets.find(name);
  if (it == mesh.node_sets.end()) {
    throw MeshError(
        fmt::format("unknown node set '{}' (known: {})", name, known_names(mesh.node_sets)));
  }
  return it->second;
}

const std::vector<ElementSide>& edge_set(const Mesh& mesh, const std::string& name) {
  const auto it = mesh.edge_sets.find(name);
  if (it == mesh.edge_sets.end()) {
    throw MeshError(
        fmt::format("unknown edge set '{}' (known: {})", name, known_names(mesh.edge_sets)));
  }
  return it->second;
}

std::vector<int> sort_along_set(const Mesh& mesh, std::vector<int> nodes) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(nodes.size());
  for (int n : nodes)
    points.push_back(mesh.nodes[n]);
  const bool along_x = spreads_along_x(points);
  std::sort(nodes.begin(), nodes.end(),
            [&](int a, int b) { return less_along(mesh.nodes[a], mesh.nodes[b], along_x); });
  return nodes;
}

void sort_edge_set(const Mesh& mesh, std::vector<ElementSide>& sides) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(sides.size());
  for (const auto& s : sides)
    points.push_back(side_midpoint(mesh, s));
  const bool along_x = spreads_along_x(points);
  std::sort(sides.begin(), sides.end(), [&](const ElementSide& a, const ElementSide& b) {
    return less_along(side_midpoint(mesh, a), side_midpoint(mesh, b), along_x);
  });
}

std::vector<int> nodes_of_sides(const Mesh& mesh, const std::vector<ElementSide>& sides) {
  std::set<int> unique;
  for (const auto& s : sides) {
    for (int n : mesh.side_nodes(s)) {
      if (n >= 0)
        unique.insert(n);
    }
  }
  return sort_along_set(mesh, std::vector<int>(unique.begin(), unique.end()));
}

std::vector<int> edge_set_nodes_sorted_along_x(const Mesh& mesh, const std::string& name) {
  const auto& sides = edge_set(mesh, name);
  if (sides.empty()) {
    throw MeshError(fmt::format("edge set '{}' is empty", name));
  }
  std::set<int> unique;
  for (const auto& s : sides) {
    for (int n : mesh.side_nodes(s)) {
      if (n >= 0)
        unique.insert(n);
    }
  }
  std::vector<int> nodes(unique.begin(), unique.end());
  std::sort(nodes.begin(), nodes.end(),
            [&](int a, int b) { return less_along(mesh.nodes[a], mesh.nodes[b], true); });
  return nodes;
}

void set_node_set_from_edge_set(Mesh& mesh, const std::string& name) {
  mesh.node_sets[name] = nodes_of_sides(mesh, edge_set(mesh, name));
}

void rebuild_edge_node_sets(Mesh& mesh) {
  for (auto& [name, nodes] : mesh.node_sets) {
    if (mesh.edge_sets.count(name) != 0) {
      nodes = nodes_of_sides(mesh, mesh.edge_sets.at(name));
    }
  }
  auto& all = mesh.node_sets["all"];
  all.resize(mesh.nodes.size());
  std::iota(all.begin(), all.end(), 0);
}

void rename_set(Mesh& mesh, const std::string& from, const std::string& to) {
  const bool has_nodes = mesh.node_sets.count(from) != 0;
  const bool has_edges = mesh.edge_sets.count(from) != 0;
  if (!has_nodes && !has_edges) {
    throw MeshError(fmt::format("rename_set: no node or edge set '{}'", from));
  }
  if (from == to) {
    return;
  }
  if (mesh.node_sets.count(to) != 0 || mesh.edge_sets.count(to) != 0) {
    throw MeshError(fmt::format("rename_set: set '{}' already exists", to));
  }
  if (has_nodes) {
    auto node = mesh.node_sets.extract(from);
    node.key() = to;
    mesh.node_sets.insert(std::move(node));
  }
  if (has_edges) {
    auto node = mesh.edge_sets.extract(from);
    node.key() = to;
    mesh.edge_sets.insert(std::move(node));
  }
}

std::vector<ElementSide> boundary_sides(const Mesh& mesh) {
  std::map<std::pair<int, int>, std::vector<ElementSide>> by_corners;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int s = 0; s < 4; ++s) {
      const int a = mesh.elements[e][s];
      const int b = mesh.elements[e][(s + 1) % 4];
      by_corners[{std::min(a, b), std::max(a, b)}].push_back({e, s});
    }
  }
  std::vector<ElementSide> sides;
  for (const auto& [key, list] : by_corners) {
    if (list.size() == 1)
      sides.push_back(list.front());
  }
  std::sort(sides.begin(), sides.end(), [](const ElementSide& a, const ElementSide& b) {
    return a.element < b.element || (a.element == b.element && a.side < b.side);
  });
  return sides;
}

std::vector<ElementSide> boundary_sides_where(
    const Mesh& mesh, const std::function<bool(const Eigen::Vector2d&)>& on) {
  std::vector<ElementSide> selected;
  for (const auto& s : boundary_sides(mesh)) {
    bool all_on = true;
    for (int n : mesh.side_nodes(s)) {
      if (n >= 0 && !on(mesh.nodes[n]))
        all_on = false;
    }
    if (all_on)
      selected.push_back(s);
  }
  sort_edge_set(mesh, selected);
  return selected;
}

std::vector<int> nodes_where(const Mesh& mesh,
                             const std::function<bool(const Eigen::Vector2d&)>& predicate) {
  std::vector<int> nodes;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    if (predicate(mesh.nodes[n]))
      nodes.push_back(n);
  }
  return nodes;
}

}  // namespace cs::solver

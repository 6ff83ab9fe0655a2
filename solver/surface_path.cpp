#include "solver/surface_path.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "solver/model.hpp"

namespace cs::solver {
namespace {

int first_corner(const Mesh& mesh, const ElementSide& s) {
  return mesh.side_nodes(s)[0];
}
int second_corner(const Mesh& mesh, const ElementSide& s) {
  return mesh.side_nodes(s)[1];
}

/// The path by sorting nodes by position (for sets that are not one chain).
void sorted_fallback(const Mesh& mesh, const std::vector<ElementSide>& sides, SurfacePath& path) {
  path.is_chain = false;
  path.closed = false;
  std::vector<int> nodes;
  for (const ElementSide& s : sides) {
    for (int n : mesh.side_nodes(s)) {
      if (n >= 0)
        nodes.push_back(n);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::sort(nodes.begin(), nodes.end(), [&](int a, int b) {
    const auto& pa = mesh.nodes[a];
    const auto& pb = mesh.nodes[b];
    return pa.x() != pb.x() ? pa.x() < pb.x() : pa.y() < pb.y();
  });
  path.nodes = nodes;
  path.sides = sides;
  path.reversed.assign(sides.size(), false);
}

}  // namespace

SurfacePath surface_path(const Mesh& mesh, const std::string& edge_set) {
  const std::vector<ElementSide>& sides = resolve_edge_set(mesh, edge_set);
  SurfacePath path;
  path.edge_set = edge_set;

  // Corner -> sides touching it.
  std::map<int, std::vector<int>> at_corner;
  for (int k = 0; k < static_cast<int>(sides.size()); ++k) {
    at_corner[first_corner(mesh, sides[k])].push_back(k);
    at_corner[second_corner(mesh, sides[k])].push_back(k);
  }
  bool chain = true;
  std::vector<int> ends;
  for (const auto& [corner, touching] : at_corner) {
    if (touching.size() > 2)
      chain = false;
    if (touching.size() == 1)
      ends.push_back(corner);
  }
  if (ends.size() != 0 && ends.size() != 2)
    chain = false;

  if (chain) {
    // Start at the smaller open end, or at the smallest corner of a loop.
    auto smaller = [&](int a, int b) {
      const auto& pa = mesh.nodes[a];
      const auto& pb = mesh.nodes[b];
      return pa.x() != pb.x() ? pa.x() < pb.x() : pa.y() < pb.y();
    };
    int start = -1;
    if (ends.size() == 2) {
      start = smaller(ends[1], ends[0]) ? ends[1] : ends[0];
    } else {
      for (const auto& [corner, touching] : at_corner) {
        if (start < 0 || smaller(corner, start))
          start = corner;
      }
      // Follow the sides' own direction around the loop.
      std::vector<int>& touching = at_corner[start];
      if (first_corner(mesh, sides[touching[0]]) != start)
        std::swap(touching[0], touching[1]);
    }
    std::vector<bool> used(sides.size(), false);
    int corner = start;
    path.nodes.push_back(corner);
    for (std::size_t step = 0; step < sides.size(); ++step) {
      int next = -1;
      for (int k : at_corner[corner]) {
        if (!used[k]) {
          next = k;
          break;
        }
      }
      if (next < 0)
        break;
      used[next] = true;
      const ElementSide& s = sides[next];
      const auto n = mesh.side_nodes(s);
      const bool reversed = n[0] != corner;
      const int far = reversed ? n[0] : n[1];
      if (n[2] >= 0)
        path.nodes.push_back(n[2]);
      path.nodes.push_back(far);
      path.sides.push_back(s);
      path.reversed.push_back(reversed);
      corner = far;
    }
    if (path.sides.size() != sides.size()) {
      chain = false;  // several pieces
    } else if (ends.empty()) {
      path.closed = true;
      path.nodes.pop_back();  // back at the start
    }
  }
  if (!chain) {
    path = SurfacePath{};
    path.edge_set = edge_set;
    sorted_fallback(mesh, sides, path);
  }

  for (int n : path.nodes)
    path.positions.push_back(mesh.nodes[n]);
  path.arc_length.assign(path.nodes.size(), 0.0);
  for (std::size_t i = 1; i < path.nodes.size(); ++i) {
    path.arc_length[i] =
        path.arc_length[i - 1] + (path.positions[i] - path.positions[i - 1]).norm();
  }
  // Side extents along the path.
  double s0 = 0.0;
  for (std::size_t k = 0; k < path.sides.size(); ++k) {
    const auto n = mesh.side_nodes(path.sides[k]);
    const Eigen::Vector2d& a = mesh.nodes[path.reversed[k] ? n[1] : n[0]];
    const Eigen::Vector2d& b = mesh.nodes[path.reversed[k] ? n[0] : n[1]];
    double length = (b - a).norm();
    if (n[2] >= 0)
      length = (mesh.nodes[n[2]] - a).norm() + (b - mesh.nodes[n[2]]).norm();
    if (!path.is_chain) {
      // Position of the side's start in the sorted order.
      const auto it =
          std::find(path.nodes.begin(), path.nodes.end(), path.reversed[k] ? n[1] : n[0]);
      s0 = path.arc_length[it - path.nodes.begin()];
    }
    path.side_start.push_back(s0);
    path.side_length.push_back(length);
    s0 += length;
  }
  return path;
}

}  // namespace cs::solver

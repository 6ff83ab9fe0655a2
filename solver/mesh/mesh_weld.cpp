#include "solver/mesh/mesh_weld.hpp"

#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include <fmt/format.h>

namespace cs::solver {
namespace {

/// The index of the welded node at x, adding it when no node lies within `tolerance`. Nodes are
/// bucketed on a grid of cell `tolerance`, so a match is in the same or a neighbouring cell.
class NodeWelder {
 public:
  NodeWelder(std::vector<Eigen::Vector2d>& nodes, double tolerance)
      : nodes_(nodes), tolerance_(tolerance) {}

  int index_of(const Eigen::Vector2d& x) {
    const long cx = std::lround(std::floor(x.x() / tolerance_));
    const long cz = std::lround(std::floor(x.y() / tolerance_));
    for (long dx = -1; dx <= 1; ++dx) {
      for (long dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find({cx + dx, cz + dz});
        if (it == cells_.end())
          continue;
        for (int n : it->second) {
          if ((nodes_[n] - x).norm() < tolerance_)
            return n;
        }
      }
    }
    nodes_.push_back(x);
    const int n = static_cast<int>(nodes_.size()) - 1;
    cells_[{cx, cz}].push_back(n);
    return n;
  }

 private:
  std::vector<Eigen::Vector2d>& nodes_;
  double tolerance_;
  std::map<std::pair<long, long>, std::vector<int>> cells_;
};

}  // namespace

Mesh weld_blocks(const std::vector<Mesh>& parts, const std::string& body_name, double tolerance) {
  if (parts.empty())
    throw MeshError("weld_blocks: no parts");
  if (!(tolerance > 0.0))
    throw MeshError(fmt::format("weld_blocks: tolerance {} (must be > 0)", tolerance));
  Mesh out;
  out.type = parts.front().type;
  out.body_names = {body_name};
  NodeWelder welder(out.nodes, tolerance);
  for (const Mesh& part : parts) {
    if (part.type != out.type)
      throw MeshError("weld_blocks: the parts differ in element type");
    std::vector<int> index(part.nodes.size());
    for (std::size_t i = 0; i < part.nodes.size(); ++i)
      index[i] = welder.index_of(part.nodes[i]);
    for (const auto& e : part.elements) {
      std::array<int, 8> welded = e;
      for (int k = 0; k < part.n_element_nodes(); ++k)
        welded[k] = index[e[k]];
      out.elements.push_back(welded);
      out.element_body.push_back(0);
    }
  }
  std::vector<int> all(out.nodes.size());
  std::iota(all.begin(), all.end(), 0);
  out.node_sets["all"] = std::move(all);
  return out;
}

}  // namespace cs::solver

#include "solver/mesh/mesh_merge.hpp"

#include <set>

#include <fmt/format.h>

namespace cs::solver {

Mesh merge_bodies(const std::vector<Mesh>& parts) {
  Mesh merged;
  if (parts.empty()) {
    return merged;
  }
  merged.type = parts.front().type;
  std::set<std::string> body_names;
  for (const Mesh& part : parts) {
    if (part.type != merged.type) {
      throw MeshError("merge_bodies: parts have different element types");
    }
    if (part.body_names.empty() && part.n_elements() > 0) {
      throw MeshError("merge_bodies: a part has elements but no body name");
    }
    if (part.element_body.size() != part.elements.size()) {
      throw MeshError(fmt::format("merge_bodies: part '{}' has {} body indices for {} elements",
                                  part.body_names.empty() ? "" : part.body_names.front(),
                                  part.element_body.size(), part.elements.size()));
    }
    const int node_offset = merged.n_nodes();
    const int element_offset = merged.n_elements();
    const int body_offset = static_cast<int>(merged.body_names.size());
    for (const auto& name : part.body_names) {
      if (!body_names.insert(name).second) {
        throw MeshError(fmt::format("merge_bodies: two bodies are named '{}'", name));
      }
      merged.body_names.push_back(name);
    }
    merged.nodes.insert(merged.nodes.end(), part.nodes.begin(), part.nodes.end());
    for (const auto& e : part.elements) {
      auto shifted = e;
      for (int& n : shifted) {
        if (n >= 0)
          n += node_offset;
      }
      merged.elements.push_back(shifted);
    }
    for (int b : part.element_body) {
      merged.element_body.push_back(b + body_offset);
    }
    const std::string prefix = part.body_names.size() == 1 ? part.body_names.front() + "." : "";
    for (const auto& [name, nodes] : part.node_sets) {
      auto& target = merged.node_sets[prefix + name];
      if (!target.empty()) {
        throw MeshError(fmt::format("merge_bodies: node set '{}' defined twice", prefix + name));
      }
      for (int n : nodes)
        target.push_back(n + node_offset);
    }
    for (const auto& [name, sides] : part.edge_sets) {
      auto& target = merged.edge_sets[prefix + name];
      if (!target.empty()) {
        throw MeshError(fmt::format("merge_bodies: edge set '{}' defined twice", prefix + name));
      }
      for (const auto& s : sides)
        target.push_back({s.element + element_offset, s.side});
    }
  }
  return merged;
}

}  // namespace cs::solver

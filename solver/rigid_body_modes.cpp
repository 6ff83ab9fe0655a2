#include "solver/rigid_body_modes.hpp"

#include <cmath>
#include <numeric>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

namespace cs::solver {
namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

void unite(std::vector<int>& parent, int a, int b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a != b)
    parent[std::max(a, b)] = std::min(a, b);
}

const char* kModeNames[3] = {"translation in x", "translation in z", "rotation"};

/// Names the unrestrained modes of one group from its prescribed DOFs.
std::vector<std::string> free_modes(const Model& model, const DofMap& dofs,
                                    const std::vector<int>& nodes) {
  const bool axi = model.analysis == AnalysisType::Axisymmetric;
  // Centroid and size of the group, to scale the rotation mode to O(1).
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int n : nodes)
    centroid += model.mesh.nodes[n];
  centroid /= static_cast<double>(nodes.size());
  double size = 0.0;
  for (int n : nodes)
    size = std::max(size, (model.mesh.nodes[n] - centroid).norm());
  if (size == 0.0)
    size = 1.0;

  const int n_modes = axi ? 1 : 3;
  Eigen::Matrix3d gram = Eigen::Matrix3d::Zero();  // M^T M over the prescribed DOFs
  for (int n : nodes) {
    const Eigen::Vector2d d = (model.mesh.nodes[n] - centroid) / size;
    for (int c = 0; c < 2; ++c) {
      if (dofs.is_free(2 * n + c))
        continue;
      Eigen::Vector3d row;
      if (axi) {
        row << (c == 1 ? 1.0 : 0.0), 0.0, 0.0;
      } else {
        row << (c == 0 ? 1.0 : 0.0), (c == 1 ? 1.0 : 0.0), (c == 0 ? -d.y() : d.x());
      }
      gram += row * row.transpose();
    }
  }
  std::vector<std::string> modes;
  if (axi) {
    if (gram(0, 0) == 0.0)
      modes.emplace_back(kModeNames[1]);
    return modes;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(gram.topLeftCorner(n_modes, n_modes));
  for (int k = 0; k < n_modes; ++k) {
    if (eig.eigenvalues()[k] > 1e-10)
      continue;
    const Eigen::Vector3d v = eig.eigenvectors().col(k).cwiseAbs();
    int dominant = 0;
    v.maxCoeff(&dominant);
    if (v[dominant] > 0.99) {
      modes.emplace_back(kModeNames[dominant]);
    } else {
      modes.emplace_back("a rigid motion (translation and rotation combined)");
    }
  }
  return modes;
}

}  // namespace

std::vector<UnrestrainedBody> find_unrestrained_bodies(
    const Model& model, const DofMap& dofs, const std::vector<std::pair<int, int>>& coupled) {
  const Mesh& mesh = model.mesh;
  const int n_bodies = model.n_bodies();
  const int nen = mesh.n_element_nodes();

  // Group bodies that share nodes or are coupled.
  std::vector<int> parent(n_bodies);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> node_body(mesh.n_nodes(), -1);
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const int b = mesh.element_body[e];
    for (int a = 0; a < nen; ++a) {
      int& owner = node_body[mesh.elements[e][a]];
      if (owner < 0) {
        owner = b;
      } else if (owner != b) {
        unite(parent, owner, b);
      }
    }
  }
  for (const auto& [a, b] : coupled) {
    if (a >= 0 && a < n_bodies && b >= 0 && b < n_bodies)
      unite(parent, a, b);
  }

  std::vector<std::vector<int>> group_nodes(n_bodies);
  std::vector<int> unattached;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    if (node_body[n] >= 0) {
      group_nodes[find_root(parent, node_body[n])].push_back(n);
    } else if (dofs.is_free(2 * n) || dofs.is_free(2 * n + 1)) {
      unattached.push_back(n);
    }
  }

  std::vector<UnrestrainedBody> result;
  for (int root = 0; root < n_bodies; ++root) {
    if (find_root(parent, root) != root || group_nodes[root].empty())
      continue;
    std::vector<std::string> modes = free_modes(model, dofs, group_nodes[root]);
    if (modes.empty())
      continue;
    UnrestrainedBody u;
    for (int b = 0; b < n_bodies; ++b) {
      if (find_root(parent, b) != root)
        continue;
      u.bodies.push_back(b);
      u.name += fmt::format("{}'{}'", u.name.empty() ? "" : " + ", mesh.body_names[b]);
    }
    u.free_modes = std::move(modes);
    result.push_back(std::move(u));
  }
  if (!unattached.empty()) {
    UnrestrainedBody u;
    u.name = fmt::format("unattached nodes (e.g. node {})", unattached.front());
    u.free_modes = {"free DOFs with no stiffness"};
    result.push_back(std::move(u));
  }
  return result;
}

std::string describe(const std::vector<UnrestrainedBody>& unrestrained) {
  std::string text;
  for (const UnrestrainedBody& u : unrestrained) {
    std::string modes;
    for (std::size_t k = 0; k < u.free_modes.size(); ++k) {
      modes += (k == 0 ? "" : k + 1 == u.free_modes.size() ? " and " : ", ") + u.free_modes[k];
    }
    if (!text.empty())
      text += "; ";
    if (u.bodies.empty()) {
      text += fmt::format("{}: {}", u.name, modes);
    } else if (u.bodies.size() == 1) {
      text += fmt::format("body {} is not restrained against {}", u.name, modes);
    } else {
      text += fmt::format("bodies {} (connected) are not restrained against {}", u.name, modes);
    }
  }
  return text;
}

}  // namespace cs::solver

#include "solver/stress_recovery.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>
#include <Eigen/LU>

#include "solver/elements/element_stiffness.hpp"
#include "solver/elements/gauss_rule.hpp"
#include "solver/patch_recovery.hpp"
#include "solver/surface_path.hpp"

namespace cs::solver {
namespace {

/// Monomials of the exact fit through an n x n Gauss grid: n = 2 bilinear, n = 3 biquadratic.
Eigen::VectorXd fit_basis(int n, const Eigen::Vector2d& p) {
  Eigen::VectorXd b(n * n);
  int k = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i)
      b[k++] = std::pow(p.x(), i) * std::pow(p.y(), j);
  }
  return b;
}

/// Extrapolation matrix E (n_nodes x n_points): nodal = E * (values at the n x n Gauss points).
Eigen::MatrixXd extrapolation_matrix(ElementType type, int n) {
  const GaussRule2D& rule = gauss_rule_2d(n);
  const int m = rule.size();
  Eigen::MatrixXd A(m, m);  // A(q, k) = basis_k(point q)
  for (int q = 0; q < m; ++q)
    A.row(q) = fit_basis(n, rule.points[q]).transpose();
  const int nen = nodes_per_element(type);
  Eigen::MatrixXd P(nen, m);  // P(a, k) = basis_k(node a)
  for (int a = 0; a < nen; ++a) {
    P.row(a) = fit_basis(n, node_natural_coordinates(type, a)).transpose();
  }
  return P * A.inverse();
}

int sampling_points(ElementType type, Q8Extrapolation rule) {
  if (type == ElementType::Q4)
    return 2;
  return rule == Q8Extrapolation::Full3x3 ? 3 : 2;
}

ElementVector element_displacements(const Mesh& mesh, int e, const Eigen::VectorXd& u) {
  const int nen = mesh.n_element_nodes();
  ElementVector u_e(2 * nen);
  for (int a = 0; a < nen; ++a) {
    u_e(2 * a) = u[2 * mesh.elements[e][a]];
    u_e(2 * a + 1) = u[2 * mesh.elements[e][a] + 1];
  }
  return u_e;
}

/// The stresses at the patch sampling points of the elements marked in `elements` (nullptr:
/// every element; patch_recovery.hpp).
ElementSamples patch_samples(const Model& model, const Eigen::VectorXd& u,
                             const std::vector<Eigen::Matrix4d>& D,
                             const std::vector<char>* elements) {
  const Mesh& mesh = model.mesh;
  const auto& points = patch_sampling_points(mesh.type);
  ElementSamples samples(mesh.n_elements());
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (elements != nullptr && !(*elements)[e])
      continue;
    const ElementGeometry g = element_geometry(mesh, model.analysis, e);
    const ElementVector u_e = element_displacements(mesh, e, u);
    samples[e].reserve(points.size());
    for (const Eigen::Vector2d& xi : points) {
      const PointKinematics k = point_kinematics(g, xi);
      samples[e].push_back({k.position, D[mesh.element_body[e]] * (k.B * u_e)});
    }
  }
  return samples;
}

/// Replaces the extrapolated, averaged values of `field` by patch-recovered ones wherever a
/// patch reaches (at the nodes of `patches`; nullptr: every node).
void apply_patch_recovery(const Model& model, const Eigen::VectorXd& u,
                          const std::vector<Eigen::Matrix4d>& D, const PatchScope* patches,
                          const std::vector<int>* node_list, StressField& field) {
  // Copied in and out at the nodes that can change: every node, or the scope's.
  std::vector<std::vector<Eigen::Vector4d>> nodal(field.nodal.size());
  auto for_each_node = [&](auto&& f) {
    for (std::size_t b = 0; b < nodal.size(); ++b) {
      if (node_list == nullptr) {
        for (std::size_t n = 0; n < nodal[b].size(); ++n)
          f(b, n);
      } else {
        for (int n : *node_list)
          f(b, static_cast<std::size_t>(n));
      }
    }
  };
  for (std::size_t b = 0; b < nodal.size(); ++b)
    nodal[b].resize(field.nodal[b].size());
  for_each_node([&](std::size_t b, std::size_t n) { nodal[b][n] = field.nodal[b][n].vector(); });
  if (patches == nullptr) {
    recover_by_patches(model.mesh, patch_samples(model, u, D, nullptr), nodal, field.nodal_count);
  } else {
    recover_by_patches(model.mesh, patch_samples(model, u, D, &patches->elements()), *patches,
                       nodal, field.nodal_count);
  }
  for_each_node(
      [&](std::size_t b, std::size_t n) { field.nodal[b][n] = Stress::from(nodal[b][n]); });
}

}  // namespace

const char* to_string(StressRecoveryMethod method) {
  switch (method) {
    case StressRecoveryMethod::GaussPoint:
      return "Gauss point";
    case StressRecoveryMethod::ExtrapolatedAveraged:
      return "extrapolated, averaged";
    case StressRecoveryMethod::PatchRecovered:
      return "superconvergent patch recovery";
  }
  return "?";
}

const char* to_string(Q8Extrapolation rule) {
  return rule == Q8Extrapolation::Full3x3 ? "3x3" : "2x2";
}

bool StressField::has_node(int node, int body) const {
  return body >= 0 && body < static_cast<int>(nodal_count.size()) && node >= 0 &&
         node < static_cast<int>(nodal_count[body].size()) && nodal_count[body][node] > 0;
}

const Stress& StressField::at_node(int node, int body) const {
  if (!has_node(node, body)) {
    throw std::out_of_range(fmt::format("no nodal stress of node {} in body {} (method: {})", node,
                                        body, to_string(method)));
  }
  return nodal[body][node];
}

const Stress& StressField::at_node(int node) const {
  int found = -1;
  for (int b = 0; b < static_cast<int>(nodal_count.size()); ++b) {
    if (!has_node(node, b))
      continue;
    if (found >= 0) {
      throw std::out_of_range(fmt::format(
          "node {} belongs to bodies {} and {}: ask for the stress of one body", node, found, b));
    }
    found = b;
  }
  return at_node(node, found);
}

namespace {

/// Where a restricted recovery works: the nodes wanted, the elements holding one (increasing)
/// and the patches that reach them.
struct RecoveryScope {
  const std::vector<int>& nodes;     ///< increasing
  const std::vector<int>& elements;  ///< increasing
  const PatchScope& patches;
};

/// recover_stresses at the nodes of `scope` (nullptr: every node). Nodal methods: only the
/// elements holding such a node are evaluated (in increasing order, as for the whole mesh, so
/// that every sum adds in the same order) and only the scope's nodes have values. GaussPoint: the
/// Gauss points of those elements.
StressField recover(const Model& model, const Eigen::VectorXd& u,
                    const StressRecoveryOptions& options, const RecoveryScope* scope) {
  const std::vector<char>* nodes = scope != nullptr ? &scope->patches.nodes() : nullptr;
  const Mesh& mesh = model.mesh;
  if (u.size() != 2 * mesh.n_nodes()) {
    throw std::invalid_argument(
        fmt::format("recover_stresses: displacement has {} entries for "
                    "{} nodes",
                    u.size(), mesh.n_nodes()));
  }
  StressField field;
  field.method = options.method;
  field.q8_extrapolation = options.q8_extrapolation;

  std::vector<Eigen::Matrix4d> D(model.materials.size());
  for (std::size_t b = 0; b < D.size(); ++b)
    D[b] = elasticity_matrix(model.materials[b]);

  const bool gauss = options.method == StressRecoveryMethod::GaussPoint;
  const int n =
      gauss ? model.element_points() : sampling_points(mesh.type, options.q8_extrapolation);
  const GaussRule2D& rule = gauss_rule_2d(n);
  const int nen = mesh.n_element_nodes();
  Eigen::MatrixXd E;
  if (!gauss) {
    E = extrapolation_matrix(mesh.type, n);
    field.nodal.resize(model.n_bodies());
    field.nodal_count.resize(model.n_bodies());
    for (int b = 0; b < model.n_bodies(); ++b) {  // zeroed in place (no copy of a prototype)
      field.nodal[b].resize(mesh.n_nodes());
      field.nodal_count[b].resize(mesh.n_nodes(), 0);
    }
  } else {
    field.gauss_points.reserve(static_cast<std::size_t>(mesh.n_elements()) * rule.size());
  }

  Eigen::MatrixXd sampled(rule.size(), 4);
  const int n_evaluated =
      scope != nullptr ? static_cast<int>(scope->elements.size()) : mesh.n_elements();
  for (int i = 0; i < n_evaluated; ++i) {
    const int e = scope != nullptr ? scope->elements[i] : i;
    const int body = mesh.element_body[e];
    const ElementGeometry g = element_geometry(mesh, model.analysis, e);
    const ElementVector u_e = element_displacements(mesh, e, u);
    for (int q = 0; q < rule.size(); ++q) {
      const PointKinematics k = point_kinematics(g, rule.points[q]);
      const Eigen::Vector4d sigma = D[body] * (k.B * u_e);
      if (gauss) {
        field.gauss_points.push_back({e, body, rule.points[q], k.position, Stress::from(sigma)});
      } else {
        sampled.row(q) = sigma.transpose();
      }
    }
    if (gauss)
      continue;
    const Eigen::MatrixXd at_nodes = E * sampled;  // nen x 4
    for (int a = 0; a < nen; ++a) {
      const int node = mesh.elements[e][a];
      Stress& s = field.nodal[body][node];
      s = Stress::from(s.vector() + at_nodes.row(a).transpose());
      ++field.nodal_count[body][node];
    }
  }
  if (!gauss) {
    auto average = [&](int b, int node) {
      const int count = field.nodal_count[b][node];
      if (count > 1)
        field.nodal[b][node] = Stress::from(field.nodal[b][node].vector() / count);
    };
    for (int b = 0; b < model.n_bodies(); ++b) {
      if (scope == nullptr) {
        for (int node = 0; node < mesh.n_nodes(); ++node)
          average(b, node);
        continue;
      }
      for (int e : scope->elements) {
        for (int a = 0; a < nen; ++a) {
          const int node = mesh.elements[e][a];
          if (!(*nodes)[node]) {  // reached by some of its elements only: no value
            field.nodal_count[b][node] = 0;
            field.nodal[b][node] = Stress{};
          }
        }
      }
      for (int node : scope->nodes)
        average(b, node);
    }
  }
  if (options.method == StressRecoveryMethod::PatchRecovered) {
    apply_patch_recovery(model, u, D, scope != nullptr ? &scope->patches : nullptr,
                         scope != nullptr ? &scope->nodes : nullptr, field);
  }
  return field;
}

}  // namespace

StressField recover_stresses(const Model& model, const Eigen::VectorXd& u,
                             const StressRecoveryOptions& options) {
  return recover(model, u, options, nullptr);
}

namespace {

/// Side coordinate t in [-1, 1] of the natural point p on side s's coordinate line.
double side_coordinate(int side, const Eigen::Vector2d& p) {
  switch (side) {
    case 0:
      return p.x();
    case 1:
      return p.y();
    case 2:
      return -p.x();
    default:
      return -p.y();
  }
}

/// Distance in natural coordinates of p from side s (0 on the side).
double distance_from_side(int side, const Eigen::Vector2d& p) {
  switch (side) {
    case 0:
      return p.y() + 1.0;
    case 1:
      return 1.0 - p.x();
    case 2:
      return 1.0 - p.y();
    default:
      return p.x() + 1.0;
  }
}

}  // namespace

std::vector<SurfaceStressSample> surface_stresses(const Model& model, const StressField& field,
                                                  const std::string& edge_set) {
  const Mesh& mesh = model.mesh;
  const SurfacePath path = surface_path(mesh, edge_set);
  std::vector<SurfaceStressSample> samples;

  if (is_nodal(field.method)) {
    // The body of each node: that of the first side (in path order) containing it.
    std::unordered_map<int, std::pair<int, int>> owner;  // node -> (element, body)
    for (const ElementSide& s : path.sides) {
      for (int n : mesh.side_nodes(s)) {
        if (n >= 0)
          owner.try_emplace(n, s.element, mesh.element_body[s.element]);
      }
    }
    for (std::size_t i = 0; i < path.nodes.size(); ++i) {
      const int node = path.nodes[i];
      const auto [element, body] = owner.at(node);
      samples.push_back(
          {node, element, body, path.positions[i], path.arc_length[i], field.at_node(node, body)});
    }
    return samples;
  }

  // GaussPoint: the row of Gauss points nearest each side.
  std::vector<int> first(mesh.n_elements() + 1, -1);
  for (int i = static_cast<int>(field.gauss_points.size()) - 1; i >= 0; --i) {
    first[field.gauss_points[i].element] = i;
  }
  for (std::size_t k = 0; k < path.sides.size(); ++k) {
    const ElementSide& s = path.sides[k];
    const int begin = first[s.element];
    if (begin < 0)
      continue;
    int end = begin;
    while (end < static_cast<int>(field.gauss_points.size()) &&
           field.gauss_points[end].element == s.element) {
      ++end;
    }
    double nearest = 1e300;
    for (int i = begin; i < end; ++i) {
      nearest = std::min(nearest, distance_from_side(s.side, field.gauss_points[i].natural));
    }
    for (int i = begin; i < end; ++i) {
      const GaussPointStress& gp = field.gauss_points[i];
      if (distance_from_side(s.side, gp.natural) > nearest + 1e-12)
        continue;
      double t = side_coordinate(s.side, gp.natural);
      if (path.reversed[k])
        t = -t;
      const double arc = path.side_start[k] + 0.5 * (t + 1.0) * path.side_length[k];
      samples.push_back({-1, gp.element, gp.body, gp.position, arc, gp.stress});
    }
  }
  std::stable_sort(samples.begin(), samples.end(),
                   [](const auto& a, const auto& b) { return a.arc_length < b.arc_length; });
  return samples;
}

namespace {

std::vector<char> path_nodes(const Mesh& mesh, const std::string& edge_set) {
  std::vector<char> nodes(mesh.n_nodes(), 0);
  for (int node : surface_path(mesh, edge_set).nodes)
    nodes[node] = 1;
  return nodes;
}

std::vector<int> elements_holding(const Mesh& mesh, const std::vector<char>& nodes) {
  std::vector<int> elements;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int a = 0; a < mesh.n_element_nodes(); ++a) {
      if (nodes[mesh.elements[e][a]]) {
        elements.push_back(e);
        break;
      }
    }
  }
  return elements;
}

}  // namespace

SurfaceStressRecovery::SurfaceStressRecovery(const Model& model, std::string edge_set)
    : model_(&model),
      edge_set_(std::move(edge_set)),
      patches_(model.mesh, model.n_bodies(), path_nodes(model.mesh, edge_set_)),
      elements_(elements_holding(model.mesh, patches_.nodes())) {
  for (int node = 0; node < model.mesh.n_nodes(); ++node) {
    if (patches_.nodes()[node])
      nodes_.push_back(node);
  }
}

std::vector<SurfaceStressSample> SurfaceStressRecovery::recover(
    const Eigen::VectorXd& u, const StressRecoveryOptions& options) const {
  const RecoveryScope scope{nodes_, elements_, patches_};
  return surface_stresses(*model_, cs::solver::recover(*model_, u, options, &scope), edge_set_);
}

std::vector<int> SurfaceStressRecovery::nodes_read() const {
  const Mesh& mesh = model_->mesh;
  std::vector<char> read(mesh.n_nodes(), 0);
  const int nen = mesh.n_element_nodes();
  const auto mark = [&](int e) {
    for (int a = 0; a < nen; ++a)
      read[mesh.elements[e][a]] = 1;
  };
  for (int e : elements_)
    mark(e);
  const std::vector<char>& patch_elements = patches_.elements();
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (patch_elements[e])
      mark(e);
  }
  std::vector<int> out;
  for (int node = 0; node < mesh.n_nodes(); ++node) {
    if (read[node])
      out.push_back(node);
  }
  return out;
}

std::vector<SurfaceStressSample> recover_surface_stresses(const Model& model,
                                                          const Eigen::VectorXd& u,
                                                          const StressRecoveryOptions& options,
                                                          const std::string& edge_set) {
  return SurfaceStressRecovery(model, edge_set).recover(u, options);
}

}  // namespace cs::solver

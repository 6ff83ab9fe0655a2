#include "solver/contact/contact_surface.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "solver/contact/contact_error.hpp"

namespace cs::solver {

namespace {

/// Area of the corner quadrilateral of element e (shoelace formula; > 0 counter-clockwise).
double corner_area(const Mesh& mesh, int e) {
  double twice = 0.0;
  for (int a = 0; a < 4; ++a) {
    const Eigen::Vector2d& p = mesh.nodes[mesh.elements[e][a]];
    const Eigen::Vector2d& q = mesh.nodes[mesh.elements[e][(a + 1) % 4]];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

}  // namespace

ContactSurface::ContactSurface(const Model& model, const std::string& edge_set,
                               const std::string& role)
    : name_(edge_set), type_(model.mesh.type), analysis_(model.analysis) {
  const Mesh& mesh = model.mesh;
  const auto it = mesh.edge_sets.find(edge_set);
  if (it == mesh.edge_sets.end()) {
    throw ContactError(fmt::format("contact: unknown {} '{}' (no such edge set)", role, edge_set));
  }
  if (it->second.empty()) {
    throw ContactError(fmt::format("contact: {} '{}' is an empty edge set", role, edge_set));
  }
  const int n_side = nodes_per_side(type_);
  for (const ElementSide& s : it->second) {
    if (s.element < 0 || s.element >= mesh.n_elements() || s.side < 0 || s.side > 3) {
      throw ContactError(
          fmt::format("contact: {} '{}' refers to side {} of element {} (mesh has "
                      "{} elements, sides 0..3)",
                      role, edge_set, s.side, s.element, mesh.n_elements()));
    }
    ContactSegment seg;
    seg.side = s;
    seg.n_nodes = n_side;
    const std::array<int, 3> nodes = mesh.side_nodes(s);
    for (int a = 0; a < n_side; ++a) {
      seg.nodes[a] = nodes[a];
      seg.x[a] = mesh.nodes[nodes[a]];
    }
    const double length = (seg.x[1] - seg.x[0]).norm();
    const double area = corner_area(mesh, s.element);
    if (!(length > 0.0) || !(area > 0.0)) {
      throw ContactError(
          fmt::format("contact: {} '{}': element {} has a degenerate side or a "
                      "non-positive area",
                      role, edge_set, s.element));
    }
    seg.depth_h = area / length;
    const int body = mesh.element_body.empty() ? 0 : mesh.element_body[s.element];
    if (body < 0 || body >= static_cast<int>(model.materials.size())) {
      throw ContactError(
          fmt::format("contact: {} '{}': element {} has no material", role, edge_set, s.element));
    }
    seg.youngs_modulus_E = model.materials[body].youngs_modulus_E;
    segments_.push_back(seg);
    Eigen::AlignedBox2d box;
    for (int a = 0; a < n_side; ++a)
      box.extend(seg.x[a]);
    boxes_.push_back(box);
    for (int a = 0; a < n_side; ++a)
      nodes_.push_back(seg.nodes[a]);
  }
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  for (int n : nodes_)
    node_positions_.push_back(mesh.nodes[n]);
}

SideShapeValues ContactSurface::shape(int /*k*/, double t) const {
  return side_shape_functions(type_, t);
}

Eigen::Vector2d ContactSurface::point(int k, double t) const {
  const SideShapeValues sv = side_shape_functions(type_, t);
  const ContactSegment& s = segments_[k];
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  for (int a = 0; a < s.n_nodes; ++a)
    x += sv.N[a] * s.x[a];
  return x;
}

Eigen::Vector2d ContactSurface::tangent(int k, double t) const {
  const SideShapeValues sv = side_shape_functions(type_, t);
  const ContactSegment& s = segments_[k];
  Eigen::Vector2d dx = Eigen::Vector2d::Zero();
  for (int a = 0; a < s.n_nodes; ++a)
    dx += sv.dN[a] * s.x[a];
  return dx;
}

Eigen::Vector2d ContactSurface::normal(int k, double t) const {
  const Eigen::Vector2d dx = tangent(k, t);
  return Eigen::Vector2d(dx.y(), -dx.x()).normalized();
}

double ContactSurface::measure(int k, double t) const {
  const double ds = tangent(k, t).norm();
  return analysis_ == AnalysisType::Axisymmetric ? ds * point(k, t).x() : ds;
}

double ContactSurface::closest_parameter(int k, const Eigen::Vector2d& p) const {
  const ContactSegment& s = segments_[k];
  const Eigen::Vector2d chord = s.x[1] - s.x[0];
  double t = std::clamp(2.0 * (p - s.x[0]).dot(chord) / chord.squaredNorm() - 1.0, -1.0, 1.0);
  if (s.n_nodes == 2)
    return t;
  // Quadratic side: Newton on f(t) = (x(t) - p) . x'(t) = 0, with x'' = x0 + x1 - 2 x2.
  const Eigen::Vector2d x2nd = s.x[0] + s.x[1] - 2.0 * s.x[2];
  for (int it = 0; it < 30; ++it) {
    const Eigen::Vector2d r = point(k, t) - p;
    const Eigen::Vector2d dx = tangent(k, t);
    const double f = r.dot(dx);
    const double df = dx.squaredNorm() + r.dot(x2nd);
    if (!(df > 0.0))
      break;
    const double next = std::clamp(t - f / df, -1.0, 1.0);
    if (std::abs(next - t) < 1e-14) {
      t = next;
      break;
    }
    t = next;
  }
  return t;
}

double ContactSurface::box_distance(int k, const Eigen::Vector2d& p) const {
  return std::sqrt(boxes_[k].squaredExteriorDistance(p));
}

}  // namespace cs::solver

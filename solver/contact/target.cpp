#include "solver/contact/target.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "solver/contact/contact_error.hpp"

namespace cs::solver {

namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

/// The end parameter (-1 or 1) of `a` at the corner node it shares with `b`, or `t` if none.
double shared_end(const ContactSegment& a, const ContactSegment& b, double t) {
  for (int end = 0; end < 2; ++end) {
    if (a.nodes[end] == b.nodes[0] || a.nodes[end] == b.nodes[1])
      return end == 0 ? -1.0 : 1.0;
  }
  return t;
}

TargetPoint project_on_surface(const ContactSurface& surface, const Eigen::Vector2d& x) {
  int best = -1, tied = -1;
  double best_t = 0.0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < surface.n_segments(); ++k) {
    // The node box bounds a straight segment; a curved Q8 side bulges by a fraction of its
    // depth at most, so a generous margin keeps the pruning safe.
    if (surface.box_distance(k, x) > best_distance + 0.5 * surface.segment(k).depth_h)
      continue;
    const double t = surface.closest_parameter(k, x);
    const double distance = (x - surface.point(k, t)).norm();
    // Equally distant segments (to kGeometricTie h) are a tie that round-off must not decide:
    // an interior projection wins over an equally distant segment end (shared corner); two
    // interior ones (a point on the bisector inside a convex target corner, e.g. a node of a
    // conformal fit against the matching node of a faceted arc) are resolved below.
    const double tie = kGeometricTie * surface.segment(k).depth_h;
    const bool interior = std::abs(t) < 1.0;
    if (distance < best_distance - tie ||
        (distance <= best_distance + tie && interior && std::abs(best_t) >= 1.0)) {
      best = k;
      best_t = t;
      best_distance = distance;
      tied = -1;
    } else if (distance <= best_distance + tie && interior && std::abs(best_t) < 1.0) {
      tied = k;
    }
  }
  // Two sides equally close: their shared node is the closest point and the direction from it
  // the normal (the bisector), symmetric in the two sides, as beyond a convex corner.
  if (tied >= 0)
    best_t = shared_end(surface.segment(best), surface.segment(tied), best_t);
  TargetPoint out;
  const Eigen::Vector2d xm = surface.point(best, best_t);
  const Eigen::Vector2d n_segment = surface.normal(best, best_t);
  const Eigen::Vector2d diff = x - xm;
  const double scale = surface.segment(best).depth_h;
  if (std::abs(best_t) < 1.0 || diff.norm() <= 1e-12 * scale) {
    out.gap = diff.dot(n_segment);
    out.normal = n_segment;
  } else {  // closest to a segment end: the normal is the direction from that node
    const double sign = diff.dot(n_segment) < 0.0 ? -1.0 : 1.0;
    out.gap = sign * diff.norm();
    out.normal = sign * diff.normalized();
  }
  out.closest = xm;
  const ContactSegment& seg = surface.segment(best);
  const SideShapeValues sv = surface.shape(best, best_t);
  out.n_master = seg.n_nodes;
  for (int a = 0; a < seg.n_nodes; ++a) {
    out.master_nodes[a] = seg.nodes[a];
    out.master_weights[a] = sv.N[a];
  }
  return out;
}

}  // namespace

ContactTarget make_target(const Model& model, const TargetSpec& spec) {
  return std::visit(Overloaded{
                        [&](const TargetSurface& s) -> ContactTarget {
                          return MeshedTarget{ContactSurface(model, s.edge_set, "target surface")};
                        },
                        [&](const RigidProfile& p) -> ContactTarget {
                          validate(p);
                          return p;
                        },
                    },
                    spec);
}

TargetSpec scale_lengths(const TargetSpec& spec, double L) {
  return std::visit(Overloaded{
                        [](const TargetSurface& s) -> TargetSpec { return s; },
                        [L](const RigidProfile& p) -> TargetSpec { return scale_lengths(p, L); },
                    },
                    spec);
}

TargetPoint project(const ContactTarget& target, const Eigen::Vector2d& x) {
  return std::visit(Overloaded{
                        [&](const MeshedTarget& m) { return project_on_surface(m.surface, x); },
                        [&](const RigidProfile& p) {
                          const ProfilePoint pp = closest_point(p, x);
                          TargetPoint out;
                          out.gap = pp.gap;
                          out.normal = pp.normal;
                          out.closest = pp.closest;
                          return out;
                        },
                    },
                    target);
}

std::vector<Eigen::Vector2d> target_breakpoints(const ContactTarget& target) {
  return std::visit(Overloaded{
                        [](const MeshedTarget& m) { return m.surface.node_positions(); },
                        [](const RigidProfile& p) { return profile_kinks(p); },
                    },
                    target);
}

std::string describe(const ContactTarget& target) {
  return std::visit(Overloaded{
                        [](const MeshedTarget& m) {
                          return fmt::format("target surface '{}'", m.surface.name());
                        },
                        [](const RigidProfile& p) { return describe(p); },
                    },
                    target);
}

}  // namespace cs::solver

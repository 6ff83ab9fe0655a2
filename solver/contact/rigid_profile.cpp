#include "solver/contact/rigid_profile.hpp"

#include <cmath>

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

/// The local frame of a punch: centre c, unit direction d into the body, face tangent t.
struct PunchFrame {
  Eigen::Vector2d c;
  Eigen::Vector2d d;
  Eigen::Vector2d t;
  Eigen::Vector2d to_global(double s, double tau) const { return c + s * t + tau * d; }
};

PunchFrame punch_frame(const Eigen::Vector2d& center, const Eigen::Vector2d& direction) {
  const Eigen::Vector2d d = direction.normalized();
  return {center, d, Eigen::Vector2d(d.y(), -d.x())};
}

/// Closest point of a punch whose flat face spans |s| <= b and whose edges are quarter circles
/// of radius re (re = 0: sharp corners), in the punch's frame.
ProfilePoint punch_closest_point(const PunchFrame& f, double b, double re,
                                 const Eigen::Vector2d& x) {
  const Eigen::Vector2d rel = x - f.c;
  const double s = rel.dot(f.t);
  const double tau = rel.dot(f.d);
  ProfilePoint out;
  if (std::abs(s) <= b) {  // above (or inside, under) the flat face
    out.gap = tau;
    out.normal = f.d;
    out.closest = f.to_global(s, 0.0);
    return out;
  }
  const double sign = s > 0.0 ? 1.0 : -1.0;
  const double qs = std::abs(s) - b;  // > 0: offset from the edge centre along the face
  const double qt = tau + re;         // offset from the edge centre along d
  if (qt >= 0.0) {                    // in front of the edge: the arc (or the corner)
    const double q = std::hypot(qs, qt);
    if (q == 0.0) {  // at the centre of the edge arc: any direction is closest; take the face's
      out.gap = -re;
      out.normal = f.d;
      out.closest = f.to_global(sign * b, 0.0);
      return out;
    }
    out.gap = q - re;
    out.normal = sign * (qs / q) * f.t + (qt / q) * f.d;
    out.closest = f.to_global(sign * (b + re * qs / q), -re + re * qt / q);
    return out;
  }
  // Beside the punch, behind the edge: the straight side |s| = b + re.
  out.gap = qs - re;
  out.normal = sign * f.t;
  out.closest = f.to_global(sign * (b + re), tau);
  return out;
}

void require_positive(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw ContactError(
        fmt::format("contact: rigid profile {} = {} (must be positive and finite)", what, value));
  }
}

void require_direction(const Eigen::Vector2d& v, const char* what) {
  if (!v.allFinite() || v.norm() == 0.0) {
    throw ContactError(
        fmt::format("contact: rigid profile {} ({}, {}) is not a direction", what, v.x(), v.y()));
  }
}

void require_finite(const Eigen::Vector2d& v, const char* what) {
  if (!v.allFinite()) {
    throw ContactError(fmt::format("contact: rigid profile {} is not finite", what));
  }
}

}  // namespace

ProfilePoint closest_point(const RigidProfile& profile, const Eigen::Vector2d& x) {
  return std::visit(Overloaded{
                        [&](const RigidPlane& p) {
                          const Eigen::Vector2d n = p.normal.normalized();
                          const double gap = (x - p.point).dot(n);
                          return ProfilePoint{gap, n, x - gap * n};
                        },
                        [&](const RigidCircle& c) {
                          const Eigen::Vector2d q = x - c.center;
                          const double r = q.norm();
                          if (r == 0.0) {
                            return ProfilePoint{-c.radius, Eigen::Vector2d(0.0, 1.0),
                                                c.center + Eigen::Vector2d(0.0, c.radius)};
                          }
                          const Eigen::Vector2d n = q / r;
                          return ProfilePoint{r - c.radius, n, c.center + c.radius * n};
                        },
                        [&](const RoundedFlatPunch& p) {
                          return punch_closest_point(punch_frame(p.face_center, p.direction),
                                                     p.half_width_b, p.edge_radius_re, x);
                        },
                        [&](const SharpFlatPunch& p) {
                          return punch_closest_point(punch_frame(p.face_center, p.direction),
                                                     p.half_width_a, 0.0, x);
                        },
                    },
                    profile);
}

std::vector<Eigen::Vector2d> profile_kinks(const RigidProfile& profile) {
  return std::visit(Overloaded{
                        [](const RigidPlane&) { return std::vector<Eigen::Vector2d>{}; },
                        [](const RigidCircle&) { return std::vector<Eigen::Vector2d>{}; },
                        [](const RoundedFlatPunch& p) {
                          const PunchFrame f = punch_frame(p.face_center, p.direction);
                          const double b = p.half_width_b;
                          const double re = p.edge_radius_re;
                          return std::vector<Eigen::Vector2d>{
                              f.to_global(-b - re, -re), f.to_global(-b, 0.0), f.to_global(b, 0.0),
                              f.to_global(b + re, -re)};
                        },
                        [](const SharpFlatPunch& p) {
                          const PunchFrame f = punch_frame(p.face_center, p.direction);
                          return std::vector<Eigen::Vector2d>{f.to_global(-p.half_width_a, 0.0),
                                                              f.to_global(p.half_width_a, 0.0)};
                        },
                    },
                    profile);
}

void validate(const RigidProfile& profile) {
  std::visit(Overloaded{
                 [](const RigidPlane& p) {
                   require_finite(p.point, "point");
                   require_direction(p.normal, "normal");
                 },
                 [](const RigidCircle& c) {
                   require_finite(c.center, "centre");
                   require_positive(c.radius, "radius R");
                 },
                 [](const RoundedFlatPunch& p) {
                   require_finite(p.face_center, "face centre");
                   require_direction(p.direction, "direction");
                   require_positive(p.half_width_b, "half-width b");
                   require_positive(p.edge_radius_re, "edge radius r_e");
                 },
                 [](const SharpFlatPunch& p) {
                   require_finite(p.face_center, "face centre");
                   require_direction(p.direction, "direction");
                   require_positive(p.half_width_a, "half-width a");
                 },
             },
             profile);
}

RigidProfile scale_lengths(const RigidProfile& profile, double L) {
  return std::visit(Overloaded{
                        [L](RigidPlane p) -> RigidProfile {
                          p.point *= L;
                          return p;
                        },
                        [L](RigidCircle c) -> RigidProfile {
                          c.center *= L;
                          c.radius *= L;
                          return c;
                        },
                        [L](RoundedFlatPunch p) -> RigidProfile {
                          p.face_center *= L;
                          p.half_width_b *= L;
                          p.edge_radius_re *= L;
                          return p;
                        },
                        [L](SharpFlatPunch p) -> RigidProfile {
                          p.face_center *= L;
                          p.half_width_a *= L;
                          return p;
                        },
                    },
                    profile);
}

std::string describe(const RigidProfile& profile) {
  return std::visit(
      Overloaded{
          [](const RigidPlane&) { return std::string("rigid plane"); },
          [](const RigidCircle& c) { return fmt::format("rigid circle R = {}", c.radius); },
          [](const RoundedFlatPunch& p) {
            return fmt::format("rigid rounded punch b = {}, r_e = {}", p.half_width_b,
                               p.edge_radius_re);
          },
          [](const SharpFlatPunch& p) {
            return fmt::format("rigid sharp punch a = {}", p.half_width_a);
          },
      },
      profile);
}

}  // namespace cs::solver

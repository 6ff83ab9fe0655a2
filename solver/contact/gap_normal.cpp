#include "solver/contact/gap_normal.hpp"

namespace cs::solver {

namespace {

constexpr double kMinCosine = 0.1;

}  // namespace

TargetPoint along_contact_normal(const TargetPoint& tp, const Eigen::Vector2d& n_contact) {
  const Eigen::Vector2d direction = -n_contact.normalized();
  const double cosine = direction.dot(tp.normal);
  if (!(cosine >= kMinCosine))
    return tp;
  TargetPoint out = tp;
  out.normal = direction;
  out.gap = tp.gap / cosine;
  return out;
}

TargetPoint oriented(const TargetPoint& tp, GapNormal normal, const Eigen::Vector2d& n_contact) {
  return normal == GapNormal::Target ? tp : along_contact_normal(tp, n_contact);
}

}  // namespace cs::solver

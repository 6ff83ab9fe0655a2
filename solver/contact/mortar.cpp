#include "solver/contact/mortar.hpp"

#include <algorithm>
#include <cmath>

namespace cs::solver {

std::vector<double> mortar_cuts(const ContactSurface& surface, int k,
                                const std::vector<Eigen::Vector2d>& points) {
  const ContactSegment& seg = surface.segment(k);
  const double length = (seg.x[1] - seg.x[0]).norm();
  std::vector<double> cuts;
  for (const Eigen::Vector2d& p : points) {
    // A point far from the segment cannot bound a piece of it; one that is not only adds a
    // harmless cut, so the test is generous.
    if (surface.box_distance(k, p) > 2.0 * length)
      continue;
    const double t = surface.closest_parameter(k, p);
    if (t > -1.0 + 1e-12 && t < 1.0 - 1e-12)
      cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(),
                         [](double a, double b) { return std::abs(a - b) < 1e-12; }),
             cuts.end());
  return cuts;
}

ConstraintSet mortar_constraints(const ContactSurface& surface, const ContactTarget& target,
                                 int n_dofs, GapNormal normal) {
  const std::vector<Eigen::Vector2d> breakpoints = target_breakpoints(target);
  return weighted_gap_constraints(
      surface, target, n_dofs, kMortarGaussPoints,
      [&](int k) { return mortar_cuts(surface, k, breakpoints); }, normal);
}

}  // namespace cs::solver

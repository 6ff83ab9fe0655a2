#include "solver/contact/contact_search.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "solver/contact/target.hpp"

namespace cs::solver {

namespace {

/// The reason of the refusal of row j, a true geometric miss.
std::string miss_reason(const ConstraintSet& set, const SearchRows& rows, int j,
                        const SearchExtent& extent) {
  const ContactConstraint& row = set.rows[j];
  const double start_h = -rows.g_start[j] / row.depth_h;
  const std::string where = fmt::format(
      "the contact point at ({:.6g}, {:.6g}) penetrates the "
      "target by {:.3g}",
      row.position.x(), row.position.y(), -rows.gap[j]);
  if (rows.movable(j)) {
    return fmt::format(
        "{} but starts {:.3g} h inside it, beyond the pinball ({} h): a geometric miss, not an "
        "approach the search can take up; check the geometry or increase the pinball",
        where, start_h, extent.pinball);
  }
  return fmt::format(
      "{} and cannot move (every DOF of it is prescribed; it starts {:.3g} h inside the "
      "target, pinball {} h); check the geometry and the supports",
      where, start_h, extent.pinball);
}

}  // namespace

bool within_search(double g_start, double depth_h, const SearchExtent& extent) {
  // Inclusive to round-off: a point exactly at the pinball radius (one element beyond a
  // punch's corner at pinball 1) is a candidate in any units, not as round-off decides.
  const double tie = 1.0 + kGeometricTie;
  if (g_start >= 0.0)
    return g_start <= extent.reach * depth_h * tie;
  return -g_start <= extent.pinball * depth_h * tie;
}

SearchReview review_search(const ConstraintSet& set, const SearchRows& rows,
                           const SearchExtent& extent) {
  SearchReview review;
  double reach = extent.reach;
  for (int j = 0; j < set.n_rows(); ++j) {
    const double h = set.rows[j].depth_h;
    if (rows.candidate_of_row[j] >= 0 || !(rows.gap[j] < -kPinballPenetration * h))
      continue;
    if (!(rows.g_start[j] > 0.0) || !rows.movable(j)) {
      review.miss = miss_reason(set, rows, j, extent);
      return review;
    }
    while (!within_search(rows.g_start[j], h, {extent.pinball, reach}))
      reach *= 2.0;
  }
  if (reach > extent.reach)
    review.reach = reach;
  return review;
}

}  // namespace cs::solver

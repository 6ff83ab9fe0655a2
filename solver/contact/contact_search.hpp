#pragma once
// The contact search: which constraint rows take part in a solve, and what is done about a row
// that ends up penetrating the target without taking part.
//
// THE LAW. A row j of reference gap g_s = g0 + B u_prescribed (the configuration the loads
// start from) and underlying element depth h is a candidate when it can move (a DOF of it is
// free) and
//     -pinball h  <=  g_s  <=  reach h        (both inclusive to round-off, kGeometricTie),
// so that a search starts as the study's pinball, |g_s| <= pinball h (reach = pinball). Rows
// outside never act. After a converged solve (every algorithm but MPC, which by definition
// ties the rows found at the start and nothing else), each row outside the candidates whose
// gap g = g0 + B u is below -kPinballPenetration h is one of two kinds:
//   - APPROACHED: it started open (g_s > reach h) and can move: the body came down onto it
//     during the iterations (e.g. the block's surface just beyond a punch's rounded corner,
//     where the reference gap grows as x^2 / 2 r_e and a fine mesh's h is small beside the
//     approach). The reach grows to pinball x 2^k, the smallest such power that holds every
//     approached row, and the analysis is solved again over the new candidate set (their DOFs
//     join the condensation: a new factorization, then the same algorithm from its start).
//     Each round admits at least the rows that penetrated, so the rounds end.
//   - A TRUE GEOMETRIC MISS: it started inside the target deeper than the pinball (a point
//     behind a thin target, an overlap the pinball was not set to hold), or it cannot move
//     (every DOF prescribed): no approach explains it, so no growth of the search is sound.
//     The result is NotConverged (ContactBeyondPinball), with a reason giving the point, its
//     starting gap in h, the pinball and the penetration.
//
// Why the reach grows in powers of two of the pinball, and only on the open side: the candidate
// set stays a function of the settings and the loads alone, never of the solves made before (a
// case's results do not depend on which cases shared its analysis), and nearby load-control
// iterates and the other algorithms on the same surface land on the same reach and share its
// factorization. Growing only the open side keeps the misses refused: an approach closes open
// gaps, it never explains a point that starts inside. Rows admitted but open carry no force, so
// the solution is the one the final search would give from the start; a solve that needs no
// growth is exactly what it was before the search could grow (bit for bit).

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/contact/constraint_set.hpp"

namespace cs::solver {

/// A gap this far below zero (relative to the element depth) counts as a penetration of a
/// row outside the candidates.
inline constexpr double kPinballPenetration = 1e-10;

/// The extent of a search, in underlying element depths h: candidates have
/// -pinball h <= g_s <= reach h. reach = pinball is the study's pinball; reach >= pinball.
struct SearchExtent {
  double pinball = 1.0;
  double reach = 1.0;
};

/// Whether a row of reference gap `g_start` and depth `depth_h` lies within `extent` (whether
/// it can move is the caller's test). NaN gaps never do.
bool within_search(double g_start, double depth_h, const SearchExtent& extent);

/// The state of every row after a converged solve, as the review reads it.
struct SearchRows {
  const Eigen::VectorXd& gap;                ///< g = g0 + B u
  const Eigen::VectorXd& g_start;            ///< g_s = g0 + B u_prescribed
  const std::vector<int>& candidate_of_row;  ///< -1 outside the candidates
  const std::function<bool(int)>& movable;   ///< whether row j has a free DOF
};

/// What the review of a converged solve finds.
struct SearchReview {
  /// > the extent's reach: the reach to solve again with (some row approached); else 0.
  double reach = 0.0;
  /// Non-empty: the reason of the refusal (a true geometric miss; wins over growing).
  std::string miss;
  bool grows() const { return miss.empty() && reach > 0.0; }
};

/// Reviews the rows outside the candidates of a solve over `extent` (see the file comment).
SearchReview review_search(const ConstraintSet& set, const SearchRows& rows,
                           const SearchExtent& extent);

}  // namespace cs::solver

#pragma once
// Enlarging a quadrant mesh without touching its inner part: the far field of a block that
// stands in for a half-space is stretched outwards, so that its outer faces move from
// `outer` to `new_outer` while every node within `inner` of the origin stays where it is.

#include <Eigen/Core>

#include "solver/mesh/mesh.hpp"

namespace cs::solver {

/// A geometric stretch of the quadrant x >= 0, z >= 0 about the origin. Distances are in the
/// maximum norm r = max(|x|, |z|), whose level lines are the squares the block's faces lie on.
struct FarFieldStretch {
  double inner = 0.0;      ///< nodes with r <= inner do not move (> 0)
  double outer = 0.0;      ///< the block's faces before (> inner)
  double new_outer = 0.0;  ///< ... and after the stretch (>= outer)
};

/// Where the stretch takes a point p with r = max(|x|, |z|): p itself for r <= inner, else
///   p * rho(r) / r,   rho(r) = inner * (r / inner)^m,   m = ln(new_outer/inner) / ln(outer/inner),
/// so rho(inner) = inner, rho(outer) = new_outer, and a square r = const goes to a square. A
/// small element at r grows by rho/r along the square and by rho' = m rho/r across it, so its
/// aspect ratio grows by m (2 for a doubled extent, 4 for eight times; up to about 1.3 m for
/// an element across the diagonal x = z, where the squares turn). Throws MeshError unless 0 < inner
/// < outer <= new_outer, all finite.
Eigen::Vector2d far_field_stretch(const FarFieldStretch& s, const Eigen::Vector2d& p);

/// Applies far_field_stretch to the corner nodes of every element and puts each Q8 mid-side
/// node at the midpoint of its side's stretched corners, so straight sides stay straight (a
/// mid-side node within `inner` moves when its side reaches beyond it)
/// (a mid-side node must sit at its side's midpoint before the call, as make_block and
/// to_quadratic place it). Elements and sets are unchanged.
void stretch_far_field(Mesh& mesh, const FarFieldStretch& s);

}  // namespace cs::solver

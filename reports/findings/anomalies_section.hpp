#pragma once
// The anomalies of the results, each explained from a computation rather than ranked:
//   1. AL and PM coincide: the augmentation never acts at the default FTOLN (iteration counts
//      equal on every mesh; the largest penetration of an AL case, from the interface checks,
//      below FTOLN h).
//   2. AL/PM node-to-surface with Q8 in axisymmetry: the peak sits on the axis, where the
//      consistent weight of a Q8 corner node, integral of N r dr over its edge, is exactly 0
//      (Gauss quadrature, below): its consistent load is 0, but node-to-surface scales its
//      penalty by the integral of |N| r dr, a spurious point force on the axis, while Lagrange
//      multipliers (exact there) take whatever force equilibrium asks.
//   3. Q8 weighted-gap rows (ss LM/MPC, mortar): why the solver's multiplier basis is
//      Bernstein (the sign-changing Lagrange corner function on the axis and beyond a target's
//      end, computed below), with the force balance and F_a peaks that result.
//   4. Fine-mesh grades after errors above 100 % on C or M (MPC): a crossing, not convergence.

#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The integral of a quadratic edge's shape function of node `node` (0, 1 the corners at
/// r = 0 and r = h, 2 the midside node) times r over the edge [0, h], by 3-point Gauss
/// quadrature (exact for this cubic integrand).
double quadratic_edge_axisymmetric_weight(int node, double h);
/// The integral of |N| r over the same edge (3-point Gauss on each half, exact between kinks).
double quadratic_edge_axisymmetric_abs_weight(int node, double h);
/// The integral of a Q8 corner function N_c = (1 - t)(1 - 2t) times a gap growing linearly
/// from the corner, g = t h, over the edge (t in [0, 1]), times r = r_e + t h (axisymmetric)
/// or 1 (plane strain): -h^3 / 60 and 0 (3-point Gauss, exact).
double corner_weighted_linear_gap(bool axisymmetric, double h);
/// The integral of the quadratic Bernstein function of node `node` ((1-t)^2, t^2, 2t(1-t) for
/// 0, 1 the corners at r = 0 and r = h, 2 the midside) times r over [0, h] (3-point Gauss).
double bernstein_axisymmetric_weight(int node, double h);
/// The same for a linear edge (nodes 0 at r = 0, 1 at r = h; 2-point Gauss, exact).
double linear_edge_axisymmetric_weight(int node, double h);

/// The section (empty when none of the anomalies occurs in the results).
std::string anomalies_section(const ResultsIndex& index);

}  // namespace cs::reports

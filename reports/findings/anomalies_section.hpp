#pragma once
// The anomalies of the results, each explained from a computation rather than ranked:
//   1. AL and PM coincide: the augmentation never acts at the default FTOLN (iteration counts
//      equal on every mesh; the largest penetration of an AL case, from the interface checks,
//      below FTOLN h).
//   2. AL/PM node-to-surface with Q8 in axisymmetry: the peak sits on the axis, where the
//      consistent weight of a Q8 corner node, integral of N r dr over its edge, is exactly 0
//      (Gauss quadrature, below), so a penalty constrains that node with zero stiffness while
//      Lagrange multipliers (exact there) enforce its gap whatever its weight.
//   3. Fine-mesh grades after errors above 100 % on C or M (MPC): a crossing, not convergence.

#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The integral of a quadratic edge's shape function of node `node` (0, 1 the corners at
/// r = 0 and r = h, 2 the midside node) times r over the edge [0, h], by 3-point Gauss
/// quadrature (exact for this cubic integrand).
double quadratic_edge_axisymmetric_weight(int node, double h);
/// The same for a linear edge (nodes 0 at r = 0, 1 at r = h; 2-point Gauss, exact).
double linear_edge_axisymmetric_weight(int node, double h);

/// The section (empty when none of the anomalies occurs in the results).
std::string anomalies_section(const ResultsIndex& index);

}  // namespace cs::reports

#pragma once
// The anomalies of the results, each explained from a computation (words:
// templates/anomalies_section.mustache):
//   1. AL = PM: the augmentation never acts at the default FTOLN (values coincide, iteration
//      counts equal, the largest penetration of an AL case far below FTOLN h).
//   2. AL/PM node-to-surface with Q8 in axisymmetry: the consistent weight of a Q8 corner node on
//      the axis is exactly 0, but node-to-surface scales its penalty by the integral of |N| r dr:
//      a spurious point force on the axis, which Lagrange multipliers do not have.
//   3. Q8 weighted-gap rows: why the multiplier basis is Bernstein (the sign-changing Lagrange
//      corner function on the axis and beyond a target's end), with the force balance and the
//      F_a peaks that result.
//   4. The luck of one mesh (grading::luck_of_one_mesh, through RowFacts): a crossing.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "reports/facts/row_facts.hpp"

namespace cs::reports {

/// The integral of a quadratic edge's shape function of node `node` (0, 1 the corners at r = 0
/// and r = h, 2 the midside node) times r over the edge [0, h] (3-point Gauss, exact).
double quadratic_edge_axisymmetric_weight(int node, double h);
/// The integral of |N| r over the same edge (3-point Gauss on each half, exact between kinks).
double quadratic_edge_axisymmetric_abs_weight(int node, double h);
/// The integral of a Q8 corner function N_c = (1 - t)(1 - 2t) times a gap growing linearly from
/// the corner, g = t h, over the edge (t in [0, 1]), times r = r_e + t h (axisymmetric) or 1
/// (plane strain): -h^3 / 60 and 0.
double corner_weighted_linear_gap(bool axisymmetric, double h);
/// The integral of the quadratic Bernstein function of node `node` ((1-t)^2, t^2, 2t(1-t) for
/// 0, 1 the corners at r = 0 and r = h, 2 the midside) times r over [0, h].
double bernstein_axisymmetric_weight(int node, double h);
/// The same for a linear edge's shape functions (nodes 0 at r = 0, 1 at r = h).
double linear_edge_axisymmetric_weight(int node, double h);

/// AL against PM on the baseline rows and cases.
/// Frictionless rows and cases only, but for the frictional rows' own count: the penetration
/// argument is about the normal contact alone.
struct AlPmFacts {
  int rows = 0;             ///< AL rows with a PM twin
  int coinciding = 0;       ///< of them, equal to the printed digits on every mesh (coincide())
  int cases = 0;            ///< AL cases
  int same_iterations = 0;  ///< of them, as many iterations as their PM twin
  std::optional<double> largest_penetration;           ///< over h, of any AL case
  int frictional_rows = 0, frictional_coinciding = 0;  ///< the same with friction
};

/// An axisymmetric row where PM ns Q8 errs by 5 % or more on F, beside LMP ns Q8 and PM ns Q4.
struct AxisPenaltyRow {
  const RowFacts* pm_q8 = nullptr;
  std::optional<double> lmp_q8, pm_q4;  ///< F errors, percent
  std::optional<bool> peak_on_axis;     ///< the F profile's largest -sigma_z/p sits at r = 0
};

/// The section's facts.
struct AnomalyFacts {
  AlPmFacts al_pm;
  std::vector<AxisPenaltyRow> axis_rows;
  /// The largest |force balance| of a Q8 weighted-row case (ss LMP/PLM, mortar; MPC aside) in
  /// axisymmetry, and its case id.
  std::optional<std::pair<double, std::string>> weighted_force_balance;
  std::optional<std::array<double, 3>> fa_q8_lmp_ss;  ///< F_a sigma_c* on C, M, F
  std::vector<const RowFacts*> luck;                  ///< rows graded by the luck of one mesh
};

/// `rows` must be row_facts(index) and outlive the result.
AnomalyFacts anomaly_facts(const ResultsIndex& index, const std::vector<RowFacts>& rows);

/// The section (empty when none of the anomalies occurs in the results).
std::string anomalies_section(const ResultsIndex& index);

}  // namespace cs::reports

#pragma once
// The linearized contact constraints of one contact pair, as every discretization produces them
// and every algorithm consumes them:
//
//   g = g0 + B u   (one row per constraint; u the global displacement vector, DOF 2 n + c),
//
// with g >= 0 open, lambda >= 0 the compressive contact force of a row (force per unit thickness
// in plane strain, per radian in axisymmetry), work lambda . g, and the force on the DOFs B^T
// lambda. Each row carries a tributary weight w > 0 (length, or r-weighted length per radian):
//   - the contact pressure of a row is lambda / w;
//   - its penalty stiffness scale is (E / h) w, E the host element's Young's modulus and h the
//     underlying element depth (see solver/contact/contact_surface.hpp), so that a penalty
//     FKN (E / h) w turns a penetration d into the pressure FKN E d / h;
//   - its underlying element depth h scales the pinball and the AL tolerance FTOLN.
//
// Every row has a tangential twin at the same point with the same weight: the relative
// tangential displacement of the contact side with respect to the target,
//
//   s = s0 + T u,   s0 = 0 (the closest-point projection leaves no tangential offset),
//
// along the target's tangent t = (n_z, -n_x) (n turned clockwise: +x for the study's n = +z).
// Friction (solver/contact/coulomb_friction.hpp) carries the tangential force lambda_T of a row,
// the force the contact side exerts on the target along t (the shear it transmits); the force on
// the DOFs is -T^T lambda_T. Frictionless analyses never read T.
//
// Nodal rows (node-to-surface, mortar, and surface-to-surface with Lagrange multipliers or MPC)
// have one row per contact node; Gauss-point rows (surface-to-surface with penalty or augmented
// Lagrangian) one row per Gauss point of each contact segment.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solver/contact/contact_surface.hpp"
#include "solver/contact/gap_normal.hpp"
#include "solver/contact/target.hpp"

namespace cs::solver {

/// A node of the contact surface and its tributary measures.
struct ContactNode {
  int node = -1;                    ///< mesh node index
  Eigen::Vector2d position;         ///< reference position
  double weight_w = 0.0;            ///< consistent tributary measure: int N_a (r) ds
  double weight_abs = 0.0;          ///< int |N_a| (r) ds > 0 (differs from w at Q8 corners)
  double depth_h = 0.0;             ///< underlying element depth, averaged with |N_a| (r) ds
  double stiffness_per_area = 0.0;  ///< E / h, averaged with |N_a| (r) ds
  /// The surface's outward unit normal at the node: the segment normals averaged with
  /// |N_a| (r) ds (GapNormal::ContactSurface rows of node-to-surface contact).
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
  /// A node whose consistent weight vanishes (the corner node on the axis of an axisymmetric Q8
  /// surface: int N_a r ds = 0) carries no consistent force, so lambda / w says nothing about
  /// its pressure; results then report the pressure of this neighbour (the adjacent mid-side
  /// node), else -1.
  int pressure_neighbour = -1;
  /// True if weight_w is too small (< 1/4 of weight_abs) to convert a force into a pressure.
  bool degenerate() const { return !(weight_w > 0.25 * weight_abs); }
};

/// What one constraint row stands for.
struct ContactConstraint {
  Eigen::Vector2d position;  ///< contact point (node or Gauss point), reference position
  int node = -1;             ///< index into ConstraintSet::nodes of a nodal row, -1 otherwise
  /// The contact nodes a row's force goes to and their shares (N_a at a Gauss point; a nodal
  /// row gives its whole force to its node): nodal force F_a = sum over rows of share x lambda.
  int n_shares = 0;
  std::array<int, 3> share_nodes{-1, -1, -1};  ///< indices into ConstraintSet::nodes
  std::array<double, 3> shares{};
  double weight_w = 0.0;             ///< tributary weight > 0: pressure = lambda / w
  double stiffness_per_area = 0.0;   ///< E / h of the host element(s)
  double depth_h = 0.0;              ///< underlying element depth
  Eigen::Vector2d normal{0.0, 1.0};  ///< target normal (averaged over a weighted row)
  /// Target tangent t = (n_z, -n_x) of `normal` (the direction of the slip s and the shear).
  Eigen::Vector2d tangent() const { return {normal.y(), -normal.x()}; }
  /// The penalty stiffness scale (E / h) w (force / length): FKN times it is the penalty.
  double stiffness_scale() const { return stiffness_per_area * weight_w; }
};

/// The linearized constraints g = g0 + B u of a contact pair.
struct ConstraintSet {
  std::vector<ContactNode> nodes;       ///< the contact surface's nodes, by mesh node index
  std::vector<ContactConstraint> rows;  ///< one per constraint
  Eigen::SparseMatrix<double, Eigen::RowMajor> B;  ///< rows x global DOFs (2 n_nodes)
  Eigen::VectorXd g0;                              ///< reference-configuration gaps
  /// The tangential rows s = s0 + T u, row for row (same points and weights as B).
  Eigen::SparseMatrix<double, Eigen::RowMajor> T;
  Eigen::VectorXd s0;  ///< reference-configuration slips (zero)
  bool nodal = true;   ///< one row per contact node (else one per Gauss point)
  /// True when a row's pressure is its multiplier coefficient lambda / w (weighted rows), false
  /// when it is a nodal force over the node's tributary weight (collocated or Gauss rows).
  bool weighted = false;
  int n_rows() const { return static_cast<int>(rows.size()); }
};

/// The nodes of `surface` with their tributary measures (Gauss quadrature of each segment).
std::vector<ContactNode> contact_nodes(const ContactSurface& surface);

/// The index of mesh node `node` in `nodes` (sorted by node), or -1.
int find_contact_node(const std::vector<ContactNode>& nodes, int node);

/// Accumulates the triplets of `scale` x the linearized gap of a contact point: +scale n N_b on
/// the contact-side nodes `slave_nodes` (shape values `slave_N`), -scale n N_i on the target's
/// nodes of `tp`. `row` is the row index.
void add_gap_triplets(int row, double scale, const TargetPoint& tp, int n_slave,
                      const std::array<int, 3>& slave_nodes, const std::array<double, 3>& slave_N,
                      std::vector<Eigen::Triplet<double>>& triplets);

/// The tangent (n_z, -n_x) of a target point's normal.
inline Eigen::Vector2d target_tangent(const TargetPoint& tp) {
  return {tp.normal.y(), -tp.normal.x()};
}

/// Accumulates the triplets of `scale` x the linearized relative displacement of a contact
/// point along `direction` (the gap for the normal, the slip for the tangent): +scale direction
/// N_b on the contact-side nodes, -scale direction N_i on the target's nodes of `tp`.
void add_direction_triplets(int row, double scale, const Eigen::Vector2d& direction,
                            const TargetPoint& tp, int n_slave,
                            const std::array<int, 3>& slave_nodes,
                            const std::array<double, 3>& slave_N,
                            std::vector<Eigen::Triplet<double>>& triplets);

/// Builds B (rows x n_dofs) from triplets, summing duplicates.
Eigen::SparseMatrix<double, Eigen::RowMajor> assemble_rows(
    int n_rows, int n_dofs, const std::vector<Eigen::Triplet<double>>& triplets);

/// Weighted-gap rows: for every contact node a, g_a = (int Phi_a g (r) ds) / w_a with
/// w_a = int Phi_a (r) ds, integrated over each segment cut at the parameters `cuts(k)` (sorted,
/// inside (-1, 1)) with `points` Gauss points per piece. Mortar cuts at the target's nodes and
/// kinks; surface-to-surface does not cut.
///
/// MULTIPLIER BASIS Phi_a: the side shape functions N_a on a Q4 side; on a Q8 side the quadratic
/// Bernstein basis (s in [0, 1] along the side from corner 0)
///   Phi_0 = (1 - s)^2 = N_0 + N_m / 4,   Phi_m = 2 s (1 - s) = N_m / 2,   Phi_1 = s^2,
/// which spans the same quadratics as N and sums to 1 (a uniform pressure and a uniform gap
/// pass exactly, the patch test), but is >= 0. The Lagrange corner function N_c = (1 - s)(1 - 2 s)
/// changes sign, so its weighted gap is no measure of penetration: it is < 0 where the gap grows
/// fast enough over the far half of a side (an axisymmetric side beyond the end of a target,
/// int N_c g r ds = -h^2 g'/60 for g = g' (r - r_c)), and on the axis of an axisymmetric surface
/// int N_c r ds = 0, so its multiplier transmits no net force. With Phi_a >= 0, g >= 0 everywhere
/// gives g_a >= 0 and every row carries a force lambda_a = int p_h Phi_a (r) ds >= 0 for p_h >= 0.
///
/// GAP NORMAL: the gap and force direction of each quadrature point (solver/contact/
/// gap_normal.hpp), the target's normal unless `normal` says the contact surface's.
ConstraintSet weighted_gap_constraints(const ContactSurface& surface, const ContactTarget& target,
                                       int n_dofs, int points,
                                       const std::function<std::vector<double>(int)>& cuts,
                                       GapNormal normal = GapNormal::Target);

}  // namespace cs::solver

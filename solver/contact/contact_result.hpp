#pragma once
// The result of a contact analysis: status, per-node contact quantities, iteration counts,
// timings and the full displacement vector (for the FE core's stress recovery).
//
// Units: positions and gaps in length; pressures in force / area (positive in compression);
// in axisymmetry forces are per radian but pressures are true pressures.
//
// Friction (settings.mu > 0): the shear is the tangential traction the contact side exerts on
// the target along the target's tangent t = (n_z, -n_x) (+x for the study's n = +z), i.e. the
// shear it transmits; the slip is the contact side's tangential displacement relative to the
// target along t. A slipping point's shear is mu p with the sign of its slip increment.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/contact/constraint_rows.hpp"
#include "solver/contact/contact_options.hpp"

namespace cs::solver {

/// Whether the contact solution is the solution of the discrete contact problem.
enum class ContactStatus {
  Converged,     ///< the algorithm's conditions hold to the tolerance
  NotConverged,  ///< see ContactFailure and the reason; values are the last iterate (if any)
};

/// Why a contact analysis did not converge.
enum class ContactFailure {
  None,                  ///< converged
  IterationLimit,        ///< the active-set iteration cap was reached
  Cycling,               ///< an active set repeated an earlier one
  AugmentationLimit,     ///< AL: the augmentation cap was reached with penetration > FTOLN h
  SingularSystem,        ///< a linear system was singular (a body held by nothing)
  NonFinite,             ///< a NaN or infinity appeared
  ContactBeyondPinball,  ///< a geometric miss penetrates the target (contact_search.hpp)
};

/// "converged" or "not converged".
constexpr const char* to_string(ContactStatus s) {
  return s == ContactStatus::Converged ? "converged" : "not converged";
}

/// "none", "iteration limit", "cycling", ...
constexpr const char* to_string(ContactFailure f) {
  switch (f) {
    case ContactFailure::None:
      return "none";
    case ContactFailure::IterationLimit:
      return "iteration limit";
    case ContactFailure::Cycling:
      return "cycling";
    case ContactFailure::AugmentationLimit:
      return "augmentation limit";
    case ContactFailure::SingularSystem:
      return "singular system";
    case ContactFailure::NonFinite:
      return "non-finite values";
    case ContactFailure::ContactBeyondPinball:
      return "contact beyond the pinball";
  }
  return "unknown";
}

/// The Coulomb state of a contact point.
enum class FrictionState {
  Open,   ///< not in contact (no force)
  Stick,  ///< |shear| <= mu p, no slip increment (LM) or an elastic one (penalty)
  Slip,   ///< |shear| = mu p, slipping in the direction of the shear
};

/// "open", "stick", "slip".
constexpr const char* to_string(FrictionState s) {
  switch (s) {
    case FrictionState::Open:
      return "open";
    case FrictionState::Stick:
      return "stick";
    case FrictionState::Slip:
      return "slip";
  }
  return "unknown";
}

/// The tangential state of every constraint row after a converged step: what the next step's
/// slip increments are measured from (friction is path dependent). Empty: the unloaded
/// reference state (no slip, no shear).
struct FrictionHistory {
  ConstraintRows rows = ConstraintRows::NodeToSurface;  ///< the row kind it belongs to
  Eigen::VectorXd slip_s;     ///< s = s0 + T u per constraint row (all rows of the set)
  Eigen::VectorXd force_t;    ///< tangential force lambda_T per row (0 outside the candidates)
  Eigen::VectorXd node_slip;  ///< s per contact node (the constraint set's node order)
  bool empty() const { return slip_s.size() == 0; }
};

/// The contact state of one node of the contact surface.
struct ContactNodeResult {
  int node = -1;             ///< mesh node index
  Eigen::Vector2d position;  ///< reference position (x|r, z)
  double gap = 0.0;          ///< normal gap, > 0 open, < 0 penetrating (mortar: weighted)
  double penetration = 0.0;  ///< max(0, -gap)
  double pressure = 0.0;     ///< contact pressure, > 0 compressive
  /// The normal contact force the node carries (> 0 compressive; per unit thickness, or per
  /// radian in axisymmetry): its multiplier (weighted rows) or its share of the rows'.
  double force = 0.0;
  bool closed = false;     ///< in contact (its constraint active / tied)
  bool candidate = false;  ///< a candidate of the final search (contact_search.hpp)
  // Friction (mu > 0; zero / Open otherwise):
  double shear = 0.0;           ///< tangential traction transmitted along t (see the file comment)
  double slip = 0.0;            ///< relative tangential displacement s (mortar, ss LM: weighted)
  double slip_increment = 0.0;  ///< s minus the previous step's s
  /// Nodal rows: the row's state. Gauss rows: Stick if a closed row sharing the node sticks,
  /// else Slip if one slips, else Open.
  FrictionState friction = FrictionState::Open;
};

/// Wall-clock seconds of a contact analysis' phases.
struct ContactTimings {
  double constraints_s = 0.0;   ///< projections, constraint rows (shared between settings)
  double condensation_s = 0.0;  ///< regularized matrix, ordering, factorization, W and d
  double analyze_s = 0.0;       ///<   of which: fill-reducing ordering, symbolic analysis
  double factorize_s = 0.0;     ///<   of which: numeric factorization
  double condense_s = 0.0;      ///<   of which: W and d from the factor (dense BLAS-3)
  double iterations_s = 0.0;    ///< active-set iterations and augmentations
  double recovery_s = 0.0;      ///< displacement recovery and results
  double total_s = 0.0;         ///< everything this solve did (shared phases counted once)
  /// The sparse factorization (the condensation onto the contact DOFs) came from an earlier
  /// solve of the same ContactAnalysis (any discretization or algorithm, same pinball).
  bool condensation_reused = false;
};

/// The result of one contact analysis.
struct ContactResult {
  ContactStatus status = ContactStatus::NotConverged;
  ContactFailure failure = ContactFailure::None;
  std::string reason;     ///< one line, empty when converged
  double residual = 0.0;  ///< last relative complementarity residual

  ContactSettings settings;       ///< what was run
  int active_set_iterations = 0;  ///< linear solves of the condensed problem
  int augmentations = 0;          ///< AL multiplier updates (normal and tangential together)
  int n_constraints = 0;          ///< constraint rows (nodes or Gauss points)
  int n_candidates = 0;           ///< candidate rows of the final search (contact_search.hpp)
  int n_contact_dofs = 0;         ///< DOFs touched by the candidate rows (condensed block)

  /// Per contact-surface node, sorted by position (x|r, then z).
  std::vector<ContactNodeResult> nodes;
  /// The largest x|r coordinate of a closed node (0 if none is closed).
  double contact_extent = 0.0;
  /// The largest contact pressure over the nodes (0 if none).
  double peak_pressure = 0.0;
  /// The largest tension (>= 0) the contact law's own variable carries: max over the rows of
  /// -lambda / w (a Gauss row: the traction at its point; a nodal row: its node's pressure; a
  /// weighted row: its multiplier coefficient). A node's pressure can pull where no row does: a
  /// Q8 corner's shape function is negative over the far half of each side, so its share of
  /// the Gauss rows' forces there pulls.
  double max_tension = 0.0;
  /// The sum of the nodes' normal contact forces: the load the interface transmits.
  double total_normal_force = 0.0;
  /// Friction: the largest |shear| over the nodes (0 without friction).
  double peak_shear = 0.0;
  /// Friction: the tangential state of every row, the start of the next load step (empty
  /// without friction or without a converged solution).
  FrictionHistory friction_history;

  ContactTimings timings;
  /// Global displacement (2 n_nodes, DOF 2 n + c), prescribed values included. Empty when no
  /// finite solution was obtained. NaN outside the nodes the caller asked for and the DOFs the
  /// contact rows read when displacement_complete is false (ContactAnalysis::recover_only_at).
  Eigen::VectorXd displacement;
  bool displacement_complete = true;

  bool converged() const { return status == ContactStatus::Converged; }
};

}  // namespace cs::solver

#pragma once
// The options of a frictionless contact analysis: two orthogonal choices (how the contact
// constraint is discretized, how it is enforced) and the settings of the enforcement.
//
// Every combination of ContactDiscretization x ContactAlgorithm is valid. The study's names map
// as follows (the suites layer keeps the study's name for its reports):
//   PM -> Penalty, AL -> AugmentedLagrangian, LMP and PLM -> LagrangeMultiplier (without
//   friction the two coincide), IMC (MPC) -> MultipointConstraint;
//   ns -> NodeToSurface, ss -> SurfaceToSurface; Mortar is the option the study lacked.
//
// Lengths that the settings scale are relative to the "underlying element depth" h of each
// contact point: the size of the host element of the contact surface normal to that surface,
// h = (element area) / (length of its contact side) (see solver/contact/contact_surface.hpp).

#include <string>

namespace cs::solver {

/// Where the contact constraint is imposed.
enum class ContactDiscretization {
  /// ns: one constraint per contact node, its gap measured at the node (collocation).
  NodeToSurface,
  /// ss: penalty and augmented Lagrangian: one constraint per Gauss point of each contact
  /// segment (2 for Q4 sides, 3 for Q8 sides); Lagrange multiplier and MPC: one constraint per
  /// contact node, the gap weighted by the node's shape function and integrated with the same
  /// Gauss points (no segmentation at target nodes).
  SurfaceToSurface,
  /// mortar: one constraint per contact node, the gap weighted by the node's shape function and
  /// integrated exactly over segments cut at the target's nodes and kinks (standard Lagrange
  /// multipliers, i.e. the trace of the contact side's displacement space).
  Mortar,
};

/// How the constraint is enforced.
enum class ContactAlgorithm {
  /// PM: contact force = k (-g) for g < 0, k = FKN x the element stiffness scale E w / h.
  Penalty,
  /// AL: penalty plus multiplier updates until every penetration <= FTOLN x h.
  AugmentedLagrangian,
  /// LMP / PLM: exact zero penetration by Lagrange multipliers (a saddle-point problem).
  LagrangeMultiplier,
  /// IMC / MPC: every constraint found within the pinball at the start is tied (g = 0, tension
  /// allowed, no separation); the others never act. As the study ran it, not improved.
  MultipointConstraint,
};

/// How the elastic system is condensed onto the contact DOFs (both give the same numbers to
/// round-off; see solver/contact/condensation.hpp).
enum class CondensationMethod {
  /// One sparse factorization with the contact DOFs ordered last (constrained AMD, or METIS
  /// where AMD's fill is high); the Schur complement is read from the trailing block of the
  /// factor. The fast path.
  TrailingFactorBlock,
  /// One sparse factorization in the FE core's own ordering and one solve per contact DOF.
  /// The simple reference path, for tests and small models (memory n x |c|).
  MultipleRightHandSides,
};

/// "ns", "ss", "mortar".
constexpr const char* to_string(ContactDiscretization d) {
  switch (d) {
    case ContactDiscretization::NodeToSurface:
      return "ns";
    case ContactDiscretization::SurfaceToSurface:
      return "ss";
    case ContactDiscretization::Mortar:
      return "mortar";
  }
  return "unknown";
}

/// "PM", "AL", "LM", "MPC".
constexpr const char* to_string(ContactAlgorithm a) {
  switch (a) {
    case ContactAlgorithm::Penalty:
      return "PM";
    case ContactAlgorithm::AugmentedLagrangian:
      return "AL";
    case ContactAlgorithm::LagrangeMultiplier:
      return "LM";
    case ContactAlgorithm::MultipointConstraint:
      return "MPC";
  }
  return "unknown";
}

/// The settings of one contact analysis.
struct ContactSettings {
  ContactDiscretization discretization = ContactDiscretization::SurfaceToSurface;
  ContactAlgorithm algorithm = ContactAlgorithm::AugmentedLagrangian;
  /// FKN: the penalty stiffness is FKN x E w / h (PM and AL); > 0. Default 1 as in ANSYS.
  double fkn = 1.0;
  /// FTOLN: AL augments until every penetration is <= FTOLN x h; > 0. Default 0.1 as in ANSYS.
  double ftoln = 0.1;
  /// Pinball radius as a multiple of the underlying element depth h (dimensionless, > 0):
  /// a contact point is a candidate when its distance to the target is <= pinball x h.
  /// Candidates are the only points that can ever close; MPC ties all of them. Default 1.
  double pinball = 1.0;
  /// Cap on the active-set iterations of one solve (per augmentation for AL); >= 1.
  int max_iterations = 50;
  /// Cap on the AL augmentations; >= 1.
  int max_augmentations = 25;
  CondensationMethod condensation = CondensationMethod::TrailingFactorBlock;
};

/// Throws ContactError with a one-line message if FKN, FTOLN or the pinball is not a positive
/// finite number, an iteration cap is below 1, or an enum holds no enumerator.
void validate(const ContactSettings& settings);

}  // namespace cs::solver

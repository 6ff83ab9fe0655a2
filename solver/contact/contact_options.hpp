#pragma once
// The options of a contact analysis: two orthogonal choices (how the contact constraint is
// discretized, how it is enforced), the settings of the enforcement, and Coulomb friction.
//
// Every combination of ContactDiscretization x ContactAlgorithm is valid. The study's names map
// as follows (the suites layer keeps the study's name for its reports):
//   PM -> Penalty, AL -> AugmentedLagrangian, IMC (MPC) -> MultipointConstraint;
//   LMP -> LagrangeMultiplier with TangentialEnforcement::Penalty (multipliers on the normal,
//   penalty on the tangent), PLM -> LagrangeMultiplier with TangentialEnforcement::
//   LagrangeMultiplier (multipliers on both); without friction (mu = 0) the two coincide;
//   ns -> NodeToSurface, ss -> SurfaceToSurface; Mortar is the option the study lacked.
//
// Friction (mu > 0, Coulomb |t| <= mu p): Penalty and AugmentedLagrangian enforce stick with a
// tangential penalty FKT x the normal penalty (AL augments it until the slip increment of every
// sticking point is <= FTOLT h); LagrangeMultiplier with the tangential enforcement chosen;
// MultipointConstraint is not defined with friction (tied rows have no slip). mu = 0 runs the
// frictionless code path unchanged, bit for bit.
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

/// How stick is enforced on the tangent when mu > 0 (see solver/contact/coulomb_friction.hpp).
enum class TangentialEnforcement {
  /// A tangential penalty kt = FKT x FKN x (E / h) w with a return mapping onto the Coulomb
  /// bound: a sticking point slips elastically by t / kt. Every algorithm but MPC; with
  /// LagrangeMultiplier the study's LMP.
  Penalty,
  /// Exact stick (zero slip increment) by tangential Lagrange multipliers: the study's PLM.
  /// Only with ContactAlgorithm::LagrangeMultiplier.
  LagrangeMultiplier,
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

/// "penalty", "LM".
constexpr const char* to_string(TangentialEnforcement t) {
  switch (t) {
    case TangentialEnforcement::Penalty:
      return "penalty";
    case TangentialEnforcement::LagrangeMultiplier:
      return "LM";
  }
  return "unknown";
}

/// The largest Coulomb coefficient accepted (a larger one is almost surely an input error).
inline constexpr double kMaxFrictionCoefficient = 10.0;

/// The settings of one contact analysis.
struct ContactSettings {
  ContactDiscretization discretization = ContactDiscretization::SurfaceToSurface;
  ContactAlgorithm algorithm = ContactAlgorithm::AugmentedLagrangian;
  /// FKN: the penalty stiffness is FKN x E w / h (PM and AL); > 0. Default 1 as in ANSYS.
  double fkn = 1.0;
  /// FTOLN: AL augments until every penetration is <= FTOLN x h; > 0. Default 0.1 as in ANSYS.
  double ftoln = 0.1;
  /// Pinball radius as a multiple of the underlying element depth h (dimensionless, > 0):
  /// a contact point is a candidate when its distance to the target is <= pinball x h at the
  /// start. Candidates are the only points that can close; a point that approaches from
  /// beyond the pinball during the iterations makes the search grow on its open side
  /// (solver/contact/contact_search.hpp). MPC ties the starting candidates only. Default 1.
  double pinball = 1.0;
  /// Cap on the active-set iterations of one solve (per augmentation for AL); >= 1.
  int max_iterations = 50;
  /// Cap on the AL augmentations; >= 1.
  int max_augmentations = 25;
  CondensationMethod condensation = CondensationMethod::TrailingFactorBlock;
  /// Coulomb friction coefficient mu: |t| <= mu p; 0 <= mu <= 10, finite. 0 = frictionless.
  double mu = 0.0;
  /// FKT: the tangential penalty is FKT x the normal penalty FKN x (E / h) w; > 0. Default 1 as
  /// in ANSYS. Used with mu > 0 by PM, AL and LMP.
  double fkt = 1.0;
  /// FTOLT: AL augments the tangential force until the slip increment of every sticking point
  /// is <= FTOLT x h; > 0. Default 1e-4: PM's elastic slip is about mu p / (FKT FKN E) h, 3e-4 h
  /// at the study's p / E = 1e-3 and mu = 0.3, so AL acts there (ANSYS's SLTO, 1 % of the contact
  /// length, would never act). Tighter values reach the augmentation cap with ss Gauss-point rows,
  /// whose exact stick over-constrains a segment next to a slipping one (augmented_lagrangian.hpp).
  double ftolt = 1e-4;
  /// How stick is enforced with ContactAlgorithm::LagrangeMultiplier (LMP or PLM).
  TangentialEnforcement tangential = TangentialEnforcement::Penalty;
  /// Whether friction acts (mu > 0).
  bool frictional() const { return mu > 0.0; }
  bool operator==(const ContactSettings&) const = default;
};

/// Throws ContactError with a one-line message if FKN, FTOLN, FKT, FTOLT or the pinball is not a
/// positive finite number, an iteration cap is below 1, an enum holds no enumerator, mu is
/// negative, not finite or above kMaxFrictionCoefficient, friction is asked of MPC, or tangential
/// Lagrange multipliers of an algorithm other than LagrangeMultiplier.
void validate(const ContactSettings& settings);

}  // namespace cs::solver

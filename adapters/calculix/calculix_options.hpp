#pragma once
// The CalculiX contact options the adapter writes into a deck.
//
// CalculiX 2.20 (ccx) offers, for 2D plane-strain and axisymmetric elements:
//   *CONTACT PAIR, TYPE=NODE TO SURFACE   node-to-face penalty springs (slave nodes)
//   *CONTACT PAIR, TYPE=SURFACE TO SURFACE face-to-face penalty (slave integration points)
//   *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR  p = K x overclosure (K: pressure / length)
//   *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD    with the two pair types above, ccx reduces
//       it to LINEAR with its defaults: K = 50 E_1 (E of the deck's first material, i.e. our
//       body 0, per unit length), sigma_inf = E_1 / 70000, c0 = 1e-3 (ccx warns so); the
//       adapter sets only c0 (data line "0, 0, c0" for node-to-surface). CalculiX's
//       Lagrange-multiplier "hard" contact is its mortar method
//   TYPE=MORTAR (and LINMORTAR, PGMORTAR, PGLINMORTAR): ccx 2.20 rejects it on 2D elements
//       ("*ERROR in catsmpcslavno: slave node ... is connected als dependent node in a MPC":
//       the 2D elements are expanded into 3D ones tied by MPCs, which mortar forbids).
// CalculiX's own options (labels, families, what each writes) are declared once, in
// calculix_manifest.hpp; options_for() there turns a label into these CalculixOptions.

#include <string>
#include <vector>

#include "solver/contact/contact_analysis.hpp"
#include "solver/model.hpp"

namespace cs::adapters::calculix {

/// *CONTACT PAIR, TYPE=...
enum class CcxContactType {
  NodeToSurface,     ///< NODE TO SURFACE
  SurfaceToSurface,  ///< SURFACE TO SURFACE
  Mortar,            ///< MORTAR: rejected by ccx 2.20 on 2D elements (kept to say so)
};

/// *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=...
enum class CcxPressureOverclosure {
  Linear,  ///< p = K g for an overclosure g > 0 (node-to-surface: quasi-bilinear, see K_tension)
  Hard,    ///< CalculiX's defaults (for ns and ss: LINEAR with K = 50 E of its first material)
};

/// "NODE TO SURFACE", "SURFACE TO SURFACE", "MORTAR" (as written in the deck).
const char* to_string(CcxContactType type);
/// "LINEAR", "HARD" (as written in the deck).
const char* to_string(CcxPressureOverclosure behavior);

/// Everything the adapter writes or runs that is not in the model.
struct CalculixOptions {
  CcxContactType contact = CcxContactType::NodeToSurface;
  CcxPressureOverclosure behavior = CcxPressureOverclosure::Linear;
  /// LINEAR: the slope K of the pressure-overclosure law (pressure / length), > 0. The suite
  /// passes K = FKN E / h, our penalty law (see options_for()).
  double penalty_K = 0.0;
  /// LINEAR with NODE TO SURFACE: the tension sigma_inf at large clearance (pressure), > 0.
  /// CalculiX's manual advises about 0.25 % of the largest stress expected.
  double tension_sigma_inf = 0.0;
  /// Axisymmetry: nodes on the axis (r = 0, or within round-off of it, as a pole placed by
  /// trigonometry) are written at r = axis_offset x the shortest element side that touches the
  /// axis (0: left on the axis). CalculiX expands axisymmetric
  /// elements by rotation; a face with a node on the axis collapses and its contact normal is
  /// undefined (ccx manual, *CONTACT PAIR): measured on the patch test, node-to-surface does not
  /// converge and surface-to-surface gives a tensile sigma_z at the axis, while with the offset
  /// both are exact. The default moves them by a millionth of an element.
  double axis_offset = 1e-6;
  /// LINEAR with NODE TO SURFACE: c0, the clearance (over the square root of the node's spring
  /// area) up to which a slave node gets a contact spring at the start of an increment.
  /// CalculiX's default 1e-3 leaves the nodes that close during the (single) increment without
  /// a spring: measured on H_p at h = a/8 with SMALL SLIDING, sigma_z at the axis +52 % and the
  /// pressure +43 %; with c0 = 0.01 to 1 both are as without SMALL SLIDING (pressure +0.01 %).
  double spring_distance_c0 = 0.1;
  /// NODE TO SURFACE: SMALL SLIDING (pair slave nodes with master faces once per increment,
  /// like our small-sliding solver). Without it ccx re-pairs in every iteration and, on the
  /// patch test, a slave node at the very end of the master surface flips in and out of
  /// contact until ccx freezes the pairing without it (sigma_z off by up to 73 %).
  bool small_sliding = true;
  /// Wall-clock limit of one ccx run in seconds; 0: none.
  double time_limit_seconds = 0.0;
  /// The program to run (searched in PATH unless it contains '/').
  std::string executable = "ccx";
  /// The job name: files job.inp, job.frd, job.sta, ... in the run directory.
  std::string job_name = "job";
};

/// Throws CalculixError with a one-line message for an option out of range (K or sigma_inf
/// missing or not finite where needed, a negative time limit, an empty executable, a job name
/// that is not a plain file stem), and UnsupportedByCalculix for mortar.
void validate(const CalculixOptions& options);

/// The scales that turn the study's dimensionless settings into CalculiX's numbers.
struct PenaltyScale {
  double youngs_modulus_E = 0.0;  ///< E of the contact (slave) body
  double depth_h = 0.0;           ///< underlying element depth of the contact surface
  double pressure_p = 1.0;        ///< the problem's pressure scale (for sigma_inf)
};

/// The scale of `pair` on `model`: E of the contact surface's body and the smallest
/// underlying element depth h of its sides (the finest elements, where contact is resolved).
/// Throws solver::ContactError for an unknown or empty contact surface.
PenaltyScale penalty_scale(const solver::Model& model, const solver::ContactPair& pair,
                           double pressure_p);

}  // namespace cs::adapters::calculix

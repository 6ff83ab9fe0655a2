#pragma once
// The similarity transformation of a model: every length times L, every modulus and every
// stress-like load times S. Linear elasticity has no intrinsic length or stress scale, so the
// scaled model's solution is the original one mapped:
//   u'(x') = L u(x' / L),   eps'(x') = eps(x' / L),   sigma'(x') = S sigma(x' / L),
// and every result normalized by a length and a pressure of the model (e.g. -sigma_z / p,
// x / a) is unchanged. (Stresses scale with S because E and the loads both scale with S, so
// strains are unchanged.)
//
// The rules, for x' = L x (in axisymmetry a force is per radian, see solver/analysis_type.hpp):
//   node coordinates            x'          = L x
//   moduli (E)                  E'          = S E          (nu unchanged)
//   tractions, pressures        t'(x')      = S t(x' / L)
//   point forces                F'          = S L F        (plane strain, per unit thickness)
//                               F'          = S L^2 F      (axisymmetric, per radian)
//   body forces (per volume)    b'(x')      = (S / L) b(x' / L)
//   prescribed displacements    u'(x')      = L u(x' / L)
// Nothing else in a Model or its Mesh carries a unit: sets are indices, quadrature orders are
// counts. A contact pair's rigid profile is geometry (solver/contact/target.hpp: scale_lengths);
// the contact settings (FKN x E / h, FTOLN x h, pinball x h) are relative and need nothing.
//
// The scaled model's callables wrap the original ones (they call them at x' / L), so state a
// problem's callables read (e.g. a load step's current load) is shared with the original.

#include "solver/model.hpp"

namespace cs::solver {

/// The factors of a similarity transformation.
struct ModelScaling {
  double length_L = 1.0;  ///< every length times L; > 0, finite
  double stress_S = 1.0;  ///< every modulus, stress and traction times S; > 0, finite

  /// The factor of a force (point force, nodal force, reaction, contact force resultant):
  /// S L per unit thickness (plane strain), S L^2 per radian (axisymmetric).
  double force_factor(AnalysisType analysis) const;
};

/// Throws ModelError with one line unless both factors are positive and finite.
void validate(const ModelScaling& scaling);

/// The scaled copy of `model` (rules in the file comment). Throws ModelError for bad factors.
Model scaled(const Model& model, const ModelScaling& scaling);

}  // namespace cs::solver

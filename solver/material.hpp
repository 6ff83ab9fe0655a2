#pragma once
// Isotropic linear-elastic material and its elasticity matrix.
//
// Stress and strain vectors of solver/ have four components, in this order:
//   0: sigma_x | sigma_r      eps_x | eps_r
//   1: sigma_z                eps_z
//   2: tau_xz  | tau_rz       gamma_xz | gamma_rz (engineering shear strain)
//   3: sigma_y | sigma_theta  eps_y = 0 (plane strain) | eps_theta = u_r / r (axisymmetric)
// One 4x4 matrix D serves both analyses: in plane strain eps_3 = 0 and row 3 of D gives the
// out-of-plane stress sigma_y = lambda (eps_x + eps_z) = nu (sigma_x + sigma_z).

#include <string>

#include <Eigen/Core>

namespace cs::solver {

/// An isotropic linear-elastic material.
struct Material {
  double youngs_modulus_E = 1.0;   ///< E > 0 (force / area)
  double poissons_ratio_nu = 0.3;  ///< 0 <= nu < 0.5
};

/// Throws ModelError unless E > 0 (finite) and 0 <= nu < 0.5; `body_name` names the body in
/// the message.
void validate(const Material& material, const std::string& body_name);

/// Lame's first parameter lambda = E nu / ((1 + nu)(1 - 2 nu)).
double lame_lambda(const Material& material);

/// Shear modulus mu = E / (2 (1 + nu)).
double shear_modulus_mu(const Material& material);

/// The 4x4 elasticity matrix in the component order of the file comment.
Eigen::Matrix4d elasticity_matrix(const Material& material);

}  // namespace cs::solver

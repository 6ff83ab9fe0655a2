#include "solver/material.hpp"

#include <cmath>

#include <fmt/format.h>

#include "solver/model_error.hpp"

namespace cs::solver {

void validate(const Material& material, const std::string& body_name) {
  const double E = material.youngs_modulus_E;
  const double nu = material.poissons_ratio_nu;
  if (!(std::isfinite(E) && E > 0.0)) {
    throw ModelError(
        fmt::format("material of body '{}': Young's modulus E = {} (must be > 0)", body_name, E));
  }
  if (!(std::isfinite(nu) && nu >= 0.0 && nu < 0.5)) {
    throw ModelError(fmt::format(
        "material of body '{}': Poisson's ratio nu = {} (must be in [0, 0.5))", body_name, nu));
  }
}

double lame_lambda(const Material& m) {
  const double nu = m.poissons_ratio_nu;
  return m.youngs_modulus_E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

double shear_modulus_mu(const Material& m) {
  return m.youngs_modulus_E / (2.0 * (1.0 + m.poissons_ratio_nu));
}

Eigen::Matrix4d elasticity_matrix(const Material& material) {
  const double lambda = lame_lambda(material);
  const double mu = shear_modulus_mu(material);
  const double diag = lambda + 2.0 * mu;
  Eigen::Matrix4d D;
  // clang-format off
  D << diag,   lambda, 0.0, lambda,
       lambda, diag,   0.0, lambda,
       0.0,    0.0,    mu,  0.0,
       lambda, lambda, 0.0, diag;
  // clang-format on
  return D;
}

}  // namespace cs::solver

#include "solver/contact/contact_options.hpp"

#include <cmath>

#include <fmt/format.h>

#include "solver/contact/contact_error.hpp"

namespace cs::solver {

namespace {

void require_positive(double value, const char* name, const char* meaning) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw ContactError(
        fmt::format("contact: {} = {} ({} must be positive and finite)", name, value, meaning));
  }
}

/// mu, FKT, FTOLT and the tangential enforcement.
void validate_friction(const ContactSettings& settings) {
  const int t = static_cast<int>(settings.tangential);
  if (t < 0 || t > static_cast<int>(TangentialEnforcement::LagrangeMultiplier)) {
    throw ContactError(fmt::format("contact: unknown tangential enforcement (enum value {})", t));
  }
  if (!std::isfinite(settings.mu) || settings.mu < 0.0) {
    throw ContactError(fmt::format(
        "contact: friction coefficient mu = {} (must be finite and >= 0)", settings.mu));
  }
  if (settings.mu > kMaxFrictionCoefficient) {
    throw ContactError(fmt::format("contact: friction coefficient mu = {} (must be <= {})",
                                   settings.mu, kMaxFrictionCoefficient));
  }
  require_positive(settings.fkt, "FKT", "the tangential penalty factor");
  require_positive(settings.ftolt, "FTOLT", "the slip tolerance factor");
  if (settings.tangential == TangentialEnforcement::LagrangeMultiplier &&
      settings.algorithm != ContactAlgorithm::LagrangeMultiplier) {
    throw ContactError(fmt::format(
        "contact: tangential Lagrange multipliers (PLM) need the Lagrange multiplier algorithm, "
        "not {}",
        to_string(settings.algorithm)));
  }
  if (settings.mu > 0.0 && settings.algorithm == ContactAlgorithm::MultipointConstraint) {
    throw ContactError("contact: friction is not defined for MPC (tied constraints have no slip)");
  }
}

}  // namespace

void validate(const ContactSettings& settings) {
  const int d = static_cast<int>(settings.discretization);
  if (d < 0 || d > static_cast<int>(ContactDiscretization::Mortar)) {
    throw ContactError(fmt::format("contact: unknown discretization (enum value {})", d));
  }
  const int a = static_cast<int>(settings.algorithm);
  if (a < 0 || a > static_cast<int>(ContactAlgorithm::MultipointConstraint)) {
    throw ContactError(fmt::format("contact: unknown algorithm (enum value {})", a));
  }
  const int c = static_cast<int>(settings.condensation);
  if (c < 0 || c > static_cast<int>(CondensationMethod::MultipleRightHandSides)) {
    throw ContactError(fmt::format("contact: unknown condensation method (enum value {})", c));
  }
  require_positive(settings.fkn, "FKN", "the penalty factor");
  require_positive(settings.ftoln, "FTOLN", "the penetration tolerance factor");
  require_positive(settings.pinball, "pinball", "the pinball radius factor");
  validate_friction(settings);
  if (settings.max_iterations < 1) {
    throw ContactError(
        fmt::format("contact: max_iterations = {} (must be >= 1)", settings.max_iterations));
  }
  if (settings.max_augmentations < 1) {
    throw ContactError(
        fmt::format("contact: max_augmentations = {} (must be >= 1)", settings.max_augmentations));
  }
}

}  // namespace cs::solver

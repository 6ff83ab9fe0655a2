#include "adapters/calculix/calculix_manifest.hpp"

#include <array>
#include <cmath>

#include "adapters/calculix/calculix_error.hpp"

#ifndef CONTACT_SUITE_ADAPTERS_DIR
#define CONTACT_SUITE_ADAPTERS_DIR ""
#endif

namespace cs::adapters::calculix {
namespace {

/// One row of the option table: what the manifest states and what the deck gets.
struct CalculixOption {
  std::string_view label;
  std::string_view discretization;
  CcxContactType contact;
  CcxPressureOverclosure behavior;
  std::string_view description;
};

constexpr std::array kOptions{
    CalculixOption{"linear-ns", "ns", CcxContactType::NodeToSurface, CcxPressureOverclosure::Linear,
                   "penalty (LINEAR, K = FKN E / h), NODE TO SURFACE, SMALL SLIDING"},
    CalculixOption{"linear-ss", "ss", CcxContactType::SurfaceToSurface,
                   CcxPressureOverclosure::Linear,
                   "penalty (LINEAR, K = FKN E / h), SURFACE TO SURFACE"},
    CalculixOption{"hard-ns", "ns", CcxContactType::NodeToSurface, CcxPressureOverclosure::Hard,
                   "penalty (HARD, K = 50 E), NODE TO SURFACE, SMALL SLIDING"},
    CalculixOption{"hard-ss", "ss", CcxContactType::SurfaceToSurface, CcxPressureOverclosure::Hard,
                   "penalty (HARD, K = 50 E), SURFACE TO SURFACE"},
};

bool positive_finite(double v) {
  return v > 0.0 && std::isfinite(v);
}

protocol::SolverManifest make_manifest() {
  protocol::SolverManifest m;
  if (const std::string adapters = CONTACT_SUITE_ADAPTERS_DIR; !adapters.empty())
    m.folder = std::filesystem::path(adapters) / kCalculixName;
  m.name = std::string(kCalculixName);
  m.description =
      "CalculiX 2.20 (Debian calculix-ccx) through its C++ adapter: penalty contact, meshed "
      "target";
  m.command = {"ccx"};
  m.version_command = {"ccx", "-v"};
  for (const auto& o : kOptions)
    m.options.push_back({std::string(o.label),
                         protocol::OptionFamily::penalty,
                         std::string(o.discretization),
                         std::string(o.description),
                         {}});
  m.supports = {protocol::Support::plane_strain, protocol::Support::axisymmetric,
                protocol::Support::meshed_target, protocol::Support::Q4, protocol::Support::Q8};
  m.time_limit_seconds = 600.0;
  return m;
}

}  // namespace

const protocol::SolverManifest& calculix_manifest() {
  static const protocol::SolverManifest manifest = make_manifest();
  return manifest;
}

CalculixOptions options_for(std::string_view label, double fkn, const PenaltyScale& scale) {
  calculix_manifest().option(label);  // ManifestError naming the options for an unknown label
  if (!positive_finite(scale.youngs_modulus_E) || !positive_finite(scale.depth_h) ||
      !positive_finite(scale.pressure_p) || !positive_finite(fkn))
    throw CalculixError("CalculiX: the penalty scale needs positive finite E, h, p and FKN");
  CalculixOptions options;
  for (const auto& o : kOptions) {
    if (o.label != label)
      continue;
    options.contact = o.contact;
    options.behavior = o.behavior;
  }
  options.penalty_K = fkn * scale.youngs_modulus_E / scale.depth_h;
  options.tension_sigma_inf = 0.0025 * scale.pressure_p;
  return options;
}

}  // namespace cs::adapters::calculix

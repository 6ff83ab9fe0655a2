#include "adapters/calculix/calculix_options.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "adapters/calculix/calculix_error.hpp"
#include "solver/contact/contact_surface.hpp"

namespace cs::adapters::calculix {
namespace {

bool positive_finite(double v) {
  return v > 0.0 && std::isfinite(v);
}

bool plain_stem(const std::string& name) {
  return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

}  // namespace

const char* to_string(CcxContactType type) {
  switch (type) {
    case CcxContactType::NodeToSurface:
      return "NODE TO SURFACE";
    case CcxContactType::SurfaceToSurface:
      return "SURFACE TO SURFACE";
    case CcxContactType::Mortar:
      return "MORTAR";
  }
  return "unknown";
}

const char* to_string(CcxPressureOverclosure behavior) {
  return behavior == CcxPressureOverclosure::Linear ? "LINEAR" : "HARD";
}

void validate(const CalculixOptions& options) {
  if (options.contact == CcxContactType::Mortar)
    throw UnsupportedByCalculix(
        "CalculiX: mortar contact is not supported on 2D elements (ccx 2.20 rejects it: the "
        "expanded plane-strain/axisymmetric elements are tied by MPCs)");
  if (options.behavior == CcxPressureOverclosure::Linear) {
    if (!positive_finite(options.penalty_K))
      throw CalculixError(
          fmt::format("CalculiX: penalty K must be positive and finite for LINEAR contact (got {})",
                      options.penalty_K));
    if (options.contact == CcxContactType::NodeToSurface &&
        !positive_finite(options.tension_sigma_inf))
      throw CalculixError(fmt::format(
          "CalculiX: sigma_inf must be positive and finite for LINEAR node-to-surface contact "
          "(got {})",
          options.tension_sigma_inf));
  }
  if (options.contact == CcxContactType::NodeToSurface &&
      !positive_finite(options.spring_distance_c0))
    throw CalculixError(fmt::format("CalculiX: c0 must be positive and finite (got {})",
                                    options.spring_distance_c0));
  if (!(options.axis_offset >= 0.0 && options.axis_offset <= 1e-3))
    throw CalculixError(
        fmt::format("CalculiX: axis offset must be in [0, 1e-3] (got {})", options.axis_offset));
  if (!(options.time_limit_seconds >= 0.0) || !std::isfinite(options.time_limit_seconds))
    throw CalculixError(fmt::format("CalculiX: time limit must be >= 0 and finite (got {})",
                                    options.time_limit_seconds));
  if (options.executable.empty())
    throw CalculixError("CalculiX: no executable given");
  if (!plain_stem(options.job_name))
    throw CalculixError("CalculiX: job name '" + options.job_name +
                        "' must be 1-64 characters of [A-Za-z0-9_-]");
}

PenaltyScale penalty_scale(const solver::Model& model, const solver::ContactPair& pair,
                           double pressure_p) {
  const solver::ContactSurface surface(model, pair.contact_surface);
  PenaltyScale scale;
  scale.pressure_p = pressure_p;
  scale.depth_h = std::numeric_limits<double>::infinity();
  for (const auto& segment : surface.segments()) {
    scale.depth_h = std::min(scale.depth_h, segment.depth_h);
    scale.youngs_modulus_E = segment.youngs_modulus_E;
  }
  return scale;
}

}  // namespace cs::adapters::calculix

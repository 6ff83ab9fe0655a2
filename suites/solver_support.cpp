#include "suites/solver_support.hpp"

#include <fmt/format.h>

namespace cs::suites {
namespace {

namespace protocol = adapters::protocol;
using protocol::Support;

/// What of `spec` on `setup` the code does not support, or "".
std::string unsupported(const CaseSpec& spec, const ProblemSetup& setup,
                        const protocol::SolverManifest& code) {
  const bool axi = setup.model.analysis == solver::AnalysisType::Axisymmetric;
  if (!code.supports_all({axi ? Support::axisymmetric : Support::plane_strain}))
    return axi ? "axisymmetric analysis" : "plane-strain analysis";
  if (!code.supports_all(
          {spec.target == TargetKind::Rigid ? Support::rigid_target : Support::meshed_target}))
    return spec.target == TargetKind::Rigid ? "a rigid target" : "a meshed target";
  if (!code.supports_all({spec.element == Element::Q8 ? Support::Q8 : Support::Q4}))
    return fmt::format("{} elements", to_string(spec.element));
  if (!setup.load_steps.empty())
    return "a load path (friction)";
  return {};
}

}  // namespace

Algorithm study_algorithm(protocol::OptionFamily family) {
  switch (family) {
    case protocol::OptionFamily::penalty:
      return Algorithm::PM;
    case protocol::OptionFamily::augmented_lagrangian:
    case protocol::OptionFamily::nitsche:
      return Algorithm::AL;
    case protocol::OptionFamily::lagrange_multiplier:
      return Algorithm::LMP;
    case protocol::OptionFamily::mpc:
      return Algorithm::MPC;
  }
  return Algorithm::AL;
}

std::string why_not_runnable(const CaseSpec& spec, const ProblemSetup& setup,
                             const protocol::SolverManifest& code) {
  if (spec.solver != SolverKind::external || spec.solver_name != code.name)
    return "the case is not for " + code.name;
  try {
    const protocol::SolverOption& option = code.option(spec.solver_option);
    if (spec.algorithm != study_algorithm(option.family) ||
        to_string(spec.contact) != option.discretization)
      return fmt::format("option '{}' is {} {}: its case id must read {}/{}", option.label,
                         protocol::to_string(option.family), option.discretization,
                         to_string(study_algorithm(option.family)), option.discretization);
  } catch (const protocol::ManifestError& e) {
    return e.what();
  }
  if (const std::string gap = unsupported(spec, setup, code); !gap.empty())
    return fmt::format("not supported by {}: {}", code.name, gap);
  return {};
}

}  // namespace cs::suites

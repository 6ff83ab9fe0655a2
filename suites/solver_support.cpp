#include "suites/solver_support.hpp"

#include <fmt/format.h>

#include "suites/problem_catalog.hpp"

namespace cs::suites {
namespace {

namespace protocol = adapters::protocol;
using protocol::Support;

/// What of `spec` (on an axisymmetric model or not, with a load path or not) `code` does not
/// support with `option`, or "": "a meshed target with option nitsche" where the option alone
/// lacks it.
std::string unsupported(const CaseSpec& spec, bool axisymmetric, bool load_path,
                        const protocol::SolverManifest& code,
                        const protocol::SolverOption& option) {
  const auto gap = [&](Support s, std::string what) {
    if (code.supports_all({s}, &option))
      return std::string();
    return code.supports_all({s}) ? fmt::format("{} with option {}", what, option.label) : what;
  };
  for (const std::string& why :
       {gap(axisymmetric ? Support::axisymmetric : Support::plane_strain,
            axisymmetric ? "axisymmetric analysis" : "plane-strain analysis"),
        gap(spec.target == TargetKind::Rigid ? Support::rigid_target : Support::meshed_target,
            spec.target == TargetKind::Rigid ? "a rigid target" : "a meshed target"),
        gap(spec.element == Element::Q8 ? Support::Q8 : Support::Q4,
            fmt::format("{} elements", to_string(spec.element)))})
    if (!why.empty())
      return why;
  return load_path ? "a load path (friction)" : "";
}

/// The option `spec` names, its family and discretization matching the case id's; "" or why not.
std::string option_mismatch(const CaseSpec& spec, const protocol::SolverManifest& code) {
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
  if (std::string why = option_mismatch(spec, code); !why.empty())
    return why;
  const std::string gap =
      unsupported(spec, setup.model.analysis == solver::AnalysisType::Axisymmetric,
                  !setup.load_steps.empty(), code, code.option(spec.solver_option));
  return gap.empty() ? gap : fmt::format("not supported by {}: {}", code.name, gap);
}

std::string why_not_offered(const CaseSpec& spec, const protocol::SolverManifest& code) {
  if (std::string why = option_mismatch(spec, code); !why.empty())
    return why;
  const std::string gap = unsupported(spec, problem_descriptor(spec.problem).record.axisymmetric,
                                      false, code, code.option(spec.solver_option));
  return gap.empty() ? gap : fmt::format("not supported by {}: {}", code.name, gap);
}

}  // namespace cs::suites

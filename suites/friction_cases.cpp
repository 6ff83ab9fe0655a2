#include "suites/friction_cases.hpp"

#include <limits>

#include <fmt/format.h>

#include "suites/suite_error.hpp"

namespace cs::suites {

std::vector<ParameterSpec> friction_parameters(double default_mu) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {
      {"mu", default_mu, 0.0, solver::kMaxFrictionCoefficient, false, true,
       "Coulomb friction coefficient mu (|shear| <= mu p)"},
      {"fkt", 1.0, 0.0, kInf, false, false,
       "tangential penalty factor FKT (PM, AL, LMP): multiplies the normal penalty"},
      {"ftolt", 1e-4, 0.0, kInf, false, false,
       "slip tolerance FTOLT (AL), as a fraction of the underlying element depth"},
  };
}

bool declares(const std::vector<ParameterSpec>& specs, std::string_view name) {
  for (const auto& s : specs) {
    if (s.name == name)
      return true;
  }
  return false;
}

void require_frictional_algorithm(const CaseSpec& spec, double mu) {
  if (spec.algorithm == Algorithm::MPC) {
    throw SuiteInputError(fmt::format(
        "{}: MPC is not defined with friction (mu = {}): its tied rows have no slip; use AL, "
        "PM, LMP or PLM",
        to_string(spec.problem), mu));
  }
}

void apply_friction(const CaseSpec& spec, const std::vector<ParameterSpec>& specs,
                    const Parameters& params, solver::ContactSettings& settings) {
  settings.tangential = spec.algorithm == Algorithm::PLM
                            ? solver::TangentialEnforcement::LagrangeMultiplier
                            : solver::TangentialEnforcement::Penalty;
  if (!declares(specs, "mu"))
    return;
  require_frictional_algorithm(spec, params.get("mu"));
  settings.mu = params.get("mu");
  settings.fkt = params.get("fkt");
  settings.ftolt = params.get("ftolt");
}

solver::ContactResult solve_load_steps(solver::ContactAnalysis& contact,
                                       const solver::ContactSettings& settings,
                                       const std::vector<solver::LoadStep>& steps) {
  std::vector<solver::ContactResult> path = contact.solve_steps(settings, steps);
  solver::ContactResult last = std::move(path.back());
  int iterations = 0, augmentations = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    iterations += path[k].active_set_iterations;
    augmentations += path[k].augmentations;
  }
  last.active_set_iterations += iterations;
  last.augmentations += augmentations;
  if (!last.converged()) {
    last.reason = fmt::format("load step '{}' ({} of {}): {}", steps[path.size() - 1].label,
                              path.size(), steps.size(), last.reason);
  }
  return last;
}

}  // namespace cs::suites

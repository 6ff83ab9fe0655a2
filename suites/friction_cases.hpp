#pragma once
// Coulomb friction in the suites: how a case's algorithm and parameters select the solver's
// friction settings, and how a friction problem's load steps are run.
//
// The study merges LMP with PLM (and AL with PM) because they coincide without friction. With
// friction they differ: LMP is Lagrange multipliers on the normal and a tangential penalty
// (FKT), PLM multipliers on both (exact stick). A problem has friction when it declares the
// parameter `mu` (suites/problems/); every other problem runs with mu = 0, the frictionless
// code path, bit for bit as before. MPC ties its rows (no slip): it is refused with friction.

#include <string_view>
#include <vector>

#include "solver/contact/contact_analysis.hpp"
#include "suites/case_spec.hpp"
#include "suites/parameters.hpp"

namespace cs::suites {

/// The friction parameters a friction problem declares: mu (0 < mu <= 10), FKT and FTOLT.
std::vector<ParameterSpec> friction_parameters(double default_mu);

/// Whether `specs` declares a parameter named `name`.
bool declares(const std::vector<ParameterSpec>& specs, std::string_view name);

/// Throws SuiteInputError "FP_p: MPC is not defined with friction (mu = 0.3): ..." for MPC;
/// friction problems call it when their case is built.
void require_frictional_algorithm(const CaseSpec& spec, double mu);

/// Sets the tangential enforcement of `settings` (PLM: Lagrange multipliers; every other
/// algorithm: penalty) and, when `specs` declares mu, mu, FKT and FTOLT from `params`.
/// Throws SuiteInputError for friction with MPC.
void apply_friction(const CaseSpec& spec, const std::vector<ParameterSpec>& specs,
                    const Parameters& params, solver::ContactSettings& settings);

/// Runs `steps` in order (ContactAnalysis::solve_steps) and returns the last step's result
/// (the first that failed, if one did) with the active-set iterations and augmentations of
/// every step added up, and the step's label in the reason of a failure.
solver::ContactResult solve_load_steps(solver::ContactAnalysis& contact,
                                       const solver::ContactSettings& settings,
                                       const std::vector<solver::LoadStep>& steps);

}  // namespace cs::suites

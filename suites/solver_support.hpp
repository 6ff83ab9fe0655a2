#pragma once
// Whether a registered code (an external code's manifest, or CalculiX's, declared in
// adapters/calculix/calculix_manifest.hpp) can solve a case: the case must name one of the
// code's options, its algorithm and contact fields must be that option's family (as a study
// algorithm) and discretization, and the analysis, target, element and load path must be among
// what the code supports. Both executors of registered codes ask this before anything runs.

#include <string>

#include "adapters/protocol/solver_manifest.hpp"
#include "suites/case_spec.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// The study algorithm an option family's rows sit under (penalty: PM, augmented Lagrangian
/// and Nitsche: AL, Lagrange multiplier: LMP, mpc: MPC).
Algorithm study_algorithm(adapters::protocol::OptionFamily family);

/// Why `spec` cannot run on `code` on `setup`, in one line, or "" when it can: "the case is not
/// for <code>", the manifest's message for an unknown option, "option '<label>' is <family>
/// <discretization>: its case id must read <algorithm>/<discretization>", or "not supported by
/// <code>: <what>" (an analysis, target, element or load path the code, or that option, does
/// not support: "a meshed target with option nitsche").
std::string why_not_runnable(const CaseSpec& spec, const ProblemSetup& setup,
                             const adapters::protocol::SolverManifest& code);

/// The same from the case alone, before any model is built (the problem's analysis, the case's
/// target and element; a load path is the model's, so only why_not_runnable sees it): what `run`
/// asks to leave out the cases a code does not offer.
std::string why_not_offered(const CaseSpec& spec, const adapters::protocol::SolverManifest& code);

}  // namespace cs::suites

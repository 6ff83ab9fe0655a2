#pragma once
// The builders of the study's problems, one file per family (patch test, Hertz, Steuermann,
// flat punch), and the pieces they share.

#include <string_view>
#include <vector>

#include "suites/problem_catalog.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites::problems {

/// The study fixes p/E = 1e-3 for the Steuermann problems; it gives no value for the others,
/// where the normalized answers do not depend on it (linear elasticity, small strains). We
/// use 1e-3 throughout so that every indentation is small.
inline constexpr double kStudyPOverE = 1e-3;

/// The parameters every problem has (suites/parameters.hpp), then `extra`.
std::vector<ParameterSpec> study_parameters(std::vector<ParameterSpec> extra);

/// `extent` (H, S, F): the block's width and depth as a multiple of the study's, in [1, 64];
/// the mesh within half the study's extent is unchanged (StudyMeshSpec::extent).
ParameterSpec extent_parameter();

/// `half_space_gap` (H, S, F): 1 measures gaps along the indented block's own normal, the
/// linearization of the half-space theory behind their exact values (solver/contact/
/// gap_normal.hpp); 0, the default, along the target's normal. Only 0 and 1 are accepted.
ParameterSpec half_space_gap_parameter();

/// Throws SuiteInputError unless `half_space_gap` (when the problem has it) is 0 or 1.
void require_half_space_gap_switch(const Parameters& params);

/// `params` with the default of parameter `name` set to `value` (which must lie in its range).
std::vector<ParameterSpec> with_default(std::vector<ParameterSpec> params, std::string_view name,
                                        double value);

ProblemSetup build_patch_test(const CaseSpec& spec, const Parameters& params);
ProblemSetup build_hertz(const CaseSpec& spec, const Parameters& params);
ProblemSetup build_steuermann(const CaseSpec& spec, const Parameters& params);
ProblemSetup build_flat_punch(const CaseSpec& spec, const Parameters& params);
ProblemSetup build_frictional_patch(const CaseSpec& spec, const Parameters& params);
ProblemSetup build_cattaneo_mindlin(const CaseSpec& spec, const Parameters& params);
ProblemSetup build_interference_fit(const CaseSpec& spec, const Parameters& params);

/// The common start of every problem: the study mesh, the analysis type, the two materials
/// (block E = 1 / (p/E), indenter E_ratio times stiffer, both with nu), symmetry (u_x = 0) on
/// both bodies' x = 0 edges. With a rigid target the indenter's nodes are all fixed (it takes
/// no part) and the pair's target is `rigid`; otherwise the target is the indenter's surface.
ProblemSetup start_setup(const CaseSpec& spec, const Parameters& params,
                         const StudyMeshSpec& mesh_spec, const solver::RigidProfile& rigid);

}  // namespace cs::suites::problems

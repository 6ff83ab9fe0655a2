#pragma once
// How a case's graded quantities are read off a solution, whichever solver produced it: the
// nodal stresses along the sampled surface and the contact pressures at the contact nodes go
// in, the quantities (value, error, grade, contact-pressure version), the surface profile and
// the exact profile come out. The built-in executor and the CalculiX executor both call these,
// so a quantity means the same thing for every solver.
//
//   value of a rule = -sigma_c(node*)/p, node* = argmax over the surface nodes of -sigma_c/p
//     (MaxOnSurface), the node nearest x = 0 (AtAxis) or nearest x = a (AtEdge);
//   error = 100 (value - exact) / exact, graded by Eq. 46 (grading/accuracy.hpp);
//   contact_pressure = pressure(node')/p with node' chosen by the same rule over the contact
//     nodes (sigma_z quantities only).

#include <vector>

#include "solver/contact/contact_result.hpp"
#include "solver/stress_recovery.hpp"
#include "suites/case_result.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// The contact pressure a solver reports at one node of the contact surface.
struct ContactPressureSample {
  double x = 0.0;         ///< reference position x (r)
  double pressure = 0.0;  ///< > 0 in compression, not normalized
};

/// The sampled surface (kSampledSurface, in path order) of a solver that reports one nodal
/// stress per node (CalculiX, imported results): `nodal_stress` is indexed by node (entries off
/// the surface are not read). Each node's value is that of the body of its surface sides, as
/// for the built-in solver's nodal recoveries.
std::vector<solver::SurfaceStressSample> surface_of_nodal_stresses(
    const ProblemSetup& setup, const std::vector<solver::Stress>& nodal_stress);

/// Fills value, error and grade of each quantity of `setup`, the contact-pressure version and
/// the surface profile (nodal -sigma_z/p and pressure/p by x/a) of `result`. Quantities read
/// off the contact solution itself (friction: stick-zone edge, the contact's peak shear) need
/// the built-in `solution`; without one (another solver) they have no value. The arc
/// quantities (IF: mean and extreme pressure) read the built-in `solution`, else another
/// code's `interface` (interface_of_displacements), else have no value.
void sample_quantities(const ProblemSetup& setup,
                       const std::vector<solver::SurfaceStressSample>& surface,
                       const std::vector<ContactPressureSample>& contact, CaseResult& result,
                       const solver::ContactResult* solution = nullptr,
                       const solver::ContactResult* interface = nullptr);

/// The exact -sigma_z/p on z = 0 at 301 points of 0 <= x <= 1.5 a (within the block); empty
/// when the problem has no exact pressure.
ExactProfile exact_profile(const ProblemSetup& setup);

/// Every quantity of the problem with no value: a case without values still names what it
/// lacks.
void mark_missing(const ProblemSetup& setup, CaseResult& result);

}  // namespace cs::suites

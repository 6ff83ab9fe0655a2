#pragma once
// The interface checks of a case (schema/interface_checks.hpp) from the built-in solver's
// contact solution: the nodal contact forces against the applied load, the largest tension of
// the contact law's own variable (solver::ContactResult::max_tension), the pressure beyond the
// exact contact patch (at the node's position where it meets the target: its deformed x when gaps
// are measured along the target's normal), the deepest penetration.

#include <vector>

#include <Eigen/Core>

#include "schema/interface_checks.hpp"
#include "solver/contact/contact_result.hpp"
#include "suites/problem_setup.hpp"
#include "suites/surface_sampling.hpp"

namespace cs::suites {

/// `applied_load` is the load the interface must carry (the sum of the z components of the
/// external loads, or a rigid punch's target load), in the units of the nodal contact forces;
/// <= 0 or non-finite: no force balance (e.g. a problem loaded in steps).
schema::InterfaceChecks check_interface(const ProblemSetup& setup,
                                        const solver::ContactResult& contact, double applied_load);

/// The load the interface carries, written once for every solver: a rigid punch's target load;
/// NaN for a problem loaded in steps (no single load to balance); else the magnitude of the z
/// resultant of the external loads `f` (one body carries them and the contact alone holds it
/// in z, the other body being supported).
double interface_load(const ProblemSetup& setup, const Eigen::VectorXd& f);

/// Another code's interface, on our model, from its displacements `u`: each surface node's
/// force is the residual K u - f there along the surface's outward normal at the node (the mean
/// of its sides'; radial on an arc, exactly z on a flat surface), counted compressive against
/// it (an interface that pulls reads negative); the total normal force sums it over every node
/// of the elements on the sampled surface (so the force balance is the equilibrium of its
/// displacement field everywhere else); its pressures are its own nodal contact pressures where
/// it writes them, else the mean of the traction against a non-negative weight at each surface
/// node, from those forces (so a traction that never pulls reads no tension, on Q8 as on Q4).
/// What the arc quantities of IF and the checks below read.
solver::ContactResult interface_of_displacements(
    const ProblemSetup& setup, const Eigen::VectorXd& u,
    const std::vector<ContactPressureSample>& pressures);

/// The checks of another code's `interface` (interface_of_displacements of `u`). The
/// penetration is not checked (absent): it needs the code's own contact geometry.
schema::InterfaceChecks check_interface_of_displacements(const ProblemSetup& setup,
                                                         const solver::ContactResult& interface,
                                                         const Eigen::VectorXd& u);

/// Both of the above in one.
schema::InterfaceChecks check_interface_of_displacements(
    const ProblemSetup& setup, const Eigen::VectorXd& u,
    const std::vector<ContactPressureSample>& pressures);

}  // namespace cs::suites

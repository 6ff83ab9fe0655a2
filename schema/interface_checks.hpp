#pragma once
// What the contact interface of one case did, beside the graded peak values: checks that a
// reviewer applies to any contact solution, whichever solver produced it.
//
//   force_balance          = (sum of the nodal contact forces - applied load) / applied load;
//                            the interface must transmit the whole load (global equilibrium);
//   max_tensile_over_p     = the largest tension / p that the contact law's own variable
//                            carries (our rows' multipliers; another code's nodal pressure,
//                            or the traction's mean at each node from its nodal forces); a
//                            frictionless contact cannot pull;
//   max_outside_over_p     = the largest contact pressure / p at nodes more than one element
//                            beyond the exact contact patch (where the exact pressure is 0);
//   max_penetration_over_h = the largest penetration over the element size at the contact.
//
// A check fails beyond its tolerance below (grading/interface_check_rules.hpp applies them); a
// check that does not apply (no single load to balance, e.g. a problem loaded in steps) is
// absent.

#include <optional>

namespace cs::schema {

/// |force_balance| above this is a failure. Equilibrium holds to the solve's accuracy: for our
/// direct solves about 1e-6 of the load on the Hertz problems (an indenter 1e6 times stiffer
/// than the block) and up to 1e-5 on the graded Steuermann meshes (measured on the C meshes,
/// tests/suites/test_interface_checks.cpp); for a code that stops its Newton iterations at a
/// residual tolerance, what that tolerance leaves: 2.3e-4 for CalculiX on the patch tests and
/// Hertz ss (its default, 0.5 % of the average nodal force). A node whose force the sum misses
/// costs at least 1e-3 of the load on these meshes, so 5e-4 separates a converged solve of
/// either kind from a missing force.
inline constexpr double kForceBalanceTolerance = 5e-4;
/// Tensile pressure above this fraction of p is a failure.
inline constexpr double kTensileTolerance = 1e-2;
/// Pressure outside the exact patch above this fraction of p is a failure.
inline constexpr double kOutsideTolerance = 1e-2;
/// Penetration above this fraction of the element size (the study's default FTOLN, 0.1) is a
/// failure.
inline constexpr double kPenetrationTolerance = 0.1;

struct InterfaceChecks {
  std::optional<double> force_balance;
  std::optional<double> max_tensile_over_p;
  std::optional<double> max_outside_over_p;
  std::optional<double> max_penetration_over_h;
};

}  // namespace cs::schema

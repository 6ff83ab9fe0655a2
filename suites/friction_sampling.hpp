#pragma once
// The graded quantities of the friction problems that are read off the contact solution rather
// than the nodal stresses: the stick zone's half-width c/a from the nodes' stick/slip states,
// and the contact solution's own peak shear beside the nodal -tau_xz/p.

#include "solver/contact/contact_result.hpp"
#include "suites/case_result.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// The stick half-width of a contact solution: on each side of x = 0, midway between the
/// outermost sticking node and the next slipping node (the stick-slip boundary lies between
/// them: one element is the resolution), the two sides averaged. All closed nodes sticking:
/// the largest |x| of a closed node; none: 0. Open nodes are skipped.
double stick_half_width(const std::vector<solver::ContactNodeResult>& nodes);

/// Whether a rule is read off the contact solution (StickZoneEdge, ContactPeakShear).
bool sampled_from_contact(SamplePoint where);

/// The graded result of a rule read off the contact solution: StickZoneEdge, c / a;
/// ContactPeakShear, the largest |shear| over the contact nodes / p.
QuantityResult contact_quantity(const QuantityRule& rule, const solver::ContactResult& contact,
                                double a, double p);

}  // namespace cs::suites

#pragma once
// The graded quantities of conformal contact (the interference fits IF_p, IF_a), read off the
// contact solution along the whole contact arc, where the exact pressure p is uniform:
//
//   p_mean = (sum_i F_i) / F_exact: the interface's resultant normal force (the nodes' normal
//     forces, per unit thickness or per radian) over the exact p times the modelled surface's
//     measure (ProblemSetup::exact_interface_force), i.e. the mean contact pressure over p;
//   p_arc = p_k / p at the contact node k where |p_i / p - 1| is largest over every node of the
//     contact surface (open ones too: they carry 0, a deviation of -100 %), so that its signed
//     error 100 (p_k / p - 1) is the largest deviation of the pressure along the arc.
//
// Both read a ContactResult: the built-in solver's, or another code's interface derived from its
// displacements (interface_checks.hpp: the residual's forces along the arc's normals, and its own
// pressures where it writes them).

#include "solver/contact/contact_result.hpp"
#include "suites/case_result.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// Whether a rule is read along the arc (InterfaceMeanPressure, ArcPressureExtreme).
bool sampled_along_arc(SamplePoint where);

/// The mean contact pressure over p: total normal force over setup.exact_interface_force.
/// NaN when the setup defines no exact interface force.
double mean_pressure_over_exact(const solver::ContactResult& contact, const ProblemSetup& setup);

/// The nodal pressure over p farthest from 1 (see the file comment); NaN without nodes.
double extreme_pressure_over_exact(const solver::ContactResult& contact, double p);

/// The graded result of an arc rule (value, error against rule.exact, grade).
QuantityResult arc_quantity(const QuantityRule& rule, const solver::ContactResult& contact,
                            const ProblemSetup& setup);

}  // namespace cs::suites

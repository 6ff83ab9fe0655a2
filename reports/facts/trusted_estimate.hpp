#pragma once
// A row's Richardson limit and GCI (schema::ErrorEstimate, computed from its values on C, M
// and F) used only where they can be trusted: one rule for "has an estimate", shared by the
// estimates appendix and the extent appendix.

#include <string>

#include "schema/row_verdict.hpp"

namespace cs::reports {

/// The smallest observed order of the values' differences an extrapolation is made from: the
/// limit lies (f_F - f_M) / (2^p - 1) beyond F, more than 2.4 times the last change below 1/2.
inline constexpr double kMinimumRichardsonOrder = 0.5;

/// A row's estimate, or why there is none to use.
struct TrustedEstimate {
  const schema::ErrorEstimate* estimate = nullptr;  ///< nullptr: none to use
  std::string note;                                 ///< why not ("pre-asymptotic (...)", ...)
};

/// The row's estimate when it is asymptotic (differences of one sign that shrink), its errors
/// are not all within the study's resolution (a patch test: nothing to extrapolate), its quantity
/// is read at a point (one read between two nodes moves by whole nodes: no power of h describes
/// it), C and M resolve it (errors below grading::kUnresolvedErrorPercent: MPC's
/// +279/+79/+8 % extrapolates to -31 %) and its order is at least kMinimumRichardsonOrder
/// (S(1) AL ns at extent 8, +0.35/+0.11/-0.13 %, order 0.035, extrapolates to -9.8 %).
/// The orders of the errors (grading::observed_order) are not asked for: they assume the
/// values converge to the exact value, and a limit that differs from it (the finite block of
/// the extent study) is what an estimate is for. Otherwise the note of the rule that refused it.
TrustedEstimate trusted_estimate(const schema::RowVerdict& row);

}  // namespace cs::reports

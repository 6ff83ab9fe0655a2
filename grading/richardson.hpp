#pragma once
// Richardson extrapolation and Roache's grid convergence index of a nonsingular quantity from
// its values on the meshes C, M, F (refinement ratio 2), and when such an estimate can be
// trusted (the estimates and extent appendices use no other). The record is
// schema::ErrorEstimate.

#include <optional>
#include <string>

#include "schema/row_verdict.hpp"

namespace cs::grading {

/// With d1 = f_C - f_M and d2 = f_M - f_F:
///   observed order  p = log2(|d1| / |d2|),
///   Richardson limit f_F + (f_F - f_M) / (2^p - 1),
///   GCI = 1.25 |d2 / f_F| / (2^p - 1) * 100 (percent; safety factor 1.25; absent for f_F = 0).
/// Not asymptotic, with a note and no estimate, when a difference is at round-off (|d| <= 1e-12
/// of the largest |f|: "differences at round-off"), d1 and d2 change sign ("oscillatory"), or
/// |d1| <= |d2| ("differences do not shrink").
schema::ErrorEstimate error_estimate(double f_c, double f_m, double f_f);

/// The smallest observed order of the values' differences an extrapolation is made from: the
/// limit lies (f_F - f_M) / (2^p - 1) beyond F, more than 2.4 times the last change below 1/2.
inline constexpr double kMinimumRichardsonOrder = 0.5;

/// The largest observed order an extrapolation is made from, per element: patch-recovered
/// stresses converge at most one order above the shape functions' degree (O(h^2) on Q4, O(h^3)
/// on Q8), so an order more than one beyond that (CM_p Q8 LMP ns, 7.0) is a coincidence of the
/// differences, not the asymptotic range.
double maximum_richardson_order(schema::Element element);

/// Whether the exact value lies within the GCI band of the row's F value:
///   |f_F - x| / |f_F| <= GCI (percent); nullopt without a GCI or an F value (or f_F = 0).
std::optional<bool> gci_bounds_error(const schema::RowVerdict& row, double exact);

/// A row's estimate, or why there is none to use.
struct TrustedEstimate {
  const schema::ErrorEstimate* estimate = nullptr;  ///< nullptr: none to use
  std::string note;                                 ///< why not ("pre-asymptotic (...)", ...)
};

/// The row's estimate when it is asymptotic (differences of one sign that shrink), its errors
/// are not all within the study's resolution (a patch test: nothing to extrapolate), its errors
/// move by more than that resolution on some pair (a settled bias: nothing to extrapolate) and
/// from M to F (a last change at the resolution makes the order noise), its
/// quantity is read at a point (one read between two nodes moves by whole nodes: no power of h
/// describes it), C and M resolve it (errors below kUnresolvedErrorPercent: MPC's +279/+79/+8 %
/// extrapolates to -31 %) and its order is at least kMinimumRichardsonOrder (S(1) AL ns at extent
/// 8, +0.35/+0.11/-0.13 %, order 0.035, extrapolates to -9.8 %) and at most
/// maximum_richardson_order. The orders of the errors
/// (observed_order) are not asked for: they assume the values converge to the exact value, and a
/// limit that differs from it (the finite block of the extent study) is what an estimate is for.
/// Otherwise the note of the rule that refused it.
TrustedEstimate trusted_estimate(const schema::RowVerdict& row);

}  // namespace cs::grading

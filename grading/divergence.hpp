#pragma once
// Whether a singular quantity (the flat punch's edge stress) diverges under refinement: the
// study's Eq. 47 and a strict verdict. The record is schema::DivergenceVerdict.
// s_C, s_M, s_F are the values on the meshes C, M, F (h halving per level).

#include "schema/row_verdict.hpp"

namespace cs::grading {

/// The growth exponents alpha of |s| ~ h^-alpha that count as divergence in the strict verdict:
/// a square-root singularity gives alpha = 1/2; the band allows half of that either way.
inline constexpr double kDivergenceExponentMin = 0.25;
inline constexpr double kDivergenceExponentMax = 0.75;

/// Eq. 47 of the study: the increments grow, |s_C - s_M| < |s_M - s_F|.
bool eq47_diverging(double s_c, double s_m, double s_f);

/// Both verdicts:
///   eq47     = eq47_diverging(s_C, s_M, s_F);
///   monotone = one sign and |s_C| < |s_M| < |s_F|;
///   exponent alpha = (log2(s_M/s_C) + log2(s_F/s_M)) / 2, when the three have one sign;
///   diverges = monotone and kDivergenceExponentMin <= alpha <= kDivergenceExponentMax.
schema::DivergenceVerdict divergence_verdict(double s_c, double s_m, double s_f);

}  // namespace cs::grading

#pragma once
// Richardson extrapolation and Roache's grid convergence index of a nonsingular quantity from
// its values on the meshes C, M, F (refinement ratio 2). The record is schema::ErrorEstimate.

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

}  // namespace cs::grading

#pragma once
// Grading of one quantity against its exact value, and of a C/M/F sequence of results.
//
// Accuracy (the study's Eq. 46), on the percentage error |value - exact| / |exact| * 100:
//   e (excellent) < 1 <= g (good) < 5 <= s (satisfactory) < 10 <= u (unsatisfactory).
//
// Converging (the study's 'c', Table 2): the error magnitudes do not grow from C to M to F
// and the fine error is smaller than the coarse one. Differences below kErrorResolutionPercent
// (0.01 %, the resolution of the study's 4-decimal values) count as equal, so that a result
// exact on every mesh (the patch tests with AL/PM, ss) is converging, as the study marks it.
//
// Diverging (the study's Eq. 47, singular problems only): |s_C - s_M| < |s_M - s_F|.

#include <optional>

#include "schema/grade.hpp"

namespace cs::suites {

using schema::Grade;
using schema::is_worse;

/// Percentage differences below this count as equal in the convergence verdict.
inline constexpr double kErrorResolutionPercent = 0.01;

/// Signed percentage error 100 (value - exact) / |exact|. Precondition: exact != 0, finite.
double error_percent(double value, double exact);

/// Eq. 46 on the magnitude of a percentage error.
Grade grade_from_error(double error_percent);

/// The converging verdict for the errors (percent, signed or not) on meshes C, M, F.
bool is_converging(double error_c, double error_m, double error_f);

/// Eq. 47 for the values on meshes C, M, F: |s_C - s_M| < |s_M - s_F|.
bool is_diverging(double value_c, double value_m, double value_f);

}  // namespace cs::suites

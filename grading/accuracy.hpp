#pragma once
// The accuracy of one computed value against its exact value: the signed percentage error and
// the study's grade of it (Eq. 46); and when two computed values are the same at the study's
// resolution. The grades themselves are vocabulary (schema/grade.hpp).

#include <optional>

#include "schema/grade.hpp"

namespace cs::grading {

/// Signed percentage error, 100 (v - x) / |x|: positive when the value exceeds the exact one,
/// whatever the sign of x. Precondition: x finite and non-zero.
double error_percent(double value, double exact);

/// Eq. 46 of the study on the magnitude of a percentage error e:
///   e (excellent) if |e| < 1, g (good) if 1 <= |e| < 5, s (satisfactory) if 5 <= |e| < 10,
///   u (unsatisfactory) if |e| >= 10 or e is NaN. A boundary belongs to the worse grade.
schema::Grade grade_of_error(double error_percent);

/// Whether a value read between two nodes, with error e and resolution r > 0 (it lies anywhere
/// in e +- r), settles its grade: |e| > r and |e| - r, |e| + r fall in one band of Eq. 46.
/// CM_p PM ss Q4 c/a, +10.49 +- 4.42 %, may be s or u: it settles nothing. r <= 0 (a value
/// read at a point) always settles.
bool read_settles_grade(double error_percent, double resolution_percent);

/// The grade of a read's best reading: Eq. 46 of max(|e| - r, 0), the best the read's
/// resolution r allows. CM_p AL ss Q8 c/a, +8.28 +- 2.21 %, is at best 6.07 %: s, whatever the
/// other quantities of its option. r <= 0: the grade of e.
schema::Grade best_reading_grade(double error_percent, double resolution_percent);

/// The grade of a read's worst reading: Eq. 46 of |e| + r (H_a Q4 a_FE, +6.25 +- 6.25 %: 12.5 %,
/// u).
schema::Grade worst_reading_grade(double error_percent, double resolution_percent);

/// Whether a read with error e and resolution r is graded `grade` or better at every reading
/// in e +- r (true), at none (false: its best reading, best_reading_grade, is worse), or
/// depends on where it lies (nullopt). r <= 0, a value read at a point: whether e is.
/// H_a Q4 a_FE at +6.25 +- 6.25 % is e at best and u at worst: open for g.
std::optional<bool> read_at_least(double error_percent, double resolution_percent,
                                  schema::Grade grade);

/// The upper bound of a grade's band of |e| (%), the bound to the next worse grade: e 1, g 5,
/// s 10; u unbounded (inf).
double grade_upper_bound(schema::Grade grade);

/// How wide a grade's band of |e| is, in points: e 1 (0 to 1 %), g 4, s 5; u unbounded (inf).
double grade_band_width(schema::Grade grade);

/// The resolution at which two computed values count as the same: 0.01 %, four decimals of a
/// value near 1 as the study prints most of its values (and the resolution of its convergence
/// flag, in points of error).
inline constexpr double kCoincidenceRelative = 1e-4;

/// Whether two values coincide at the study's resolution:
///   |a - b| <= kCoincidenceRelative max(|a|, |b|).
bool values_coincide(double a, double b);

}  // namespace cs::grading

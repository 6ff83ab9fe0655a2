#pragma once
// The study's unit of assessment: one quantity of one problem with one option set, on the
// C, M and F meshes; graded on the finest mesh present (Table 2) and checked for convergence
// or, for the singular problems, divergence (Eq. 47). Computed by suites/ (the grading rules),
// recorded in results.json, read by the gate and the report.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "schema/case_spec.hpp"
#include "schema/grade.hpp"
#include "schema/quantity.hpp"

namespace cs::schema {

/// Errors below this (percent) are round-off: no order is fitted to them.
inline constexpr double kErrorNoiseFloorPercent = 1e-6;

/// Error estimate of a nonsingular row from its three meshes (refinement ratio 2): the
/// observed order p = log2(|f_C - f_M| / |f_M - f_F|), the Richardson limit
/// f_F + (f_F - f_M)/(2^p - 1) and Roache's grid convergence index of the fine value,
/// GCI = 1.25 |(f_F - f_M)/f_F| / (2^p - 1) (percent). `asymptotic` is false, and the estimate
/// left out, when the sequence is oscillatory or diverging or its differences are at round-off.
struct ErrorEstimate {
  bool asymptotic = false;
  std::optional<double> observed_order;
  std::optional<double> richardson;
  std::optional<double> gci_percent;
  std::string note;  ///< why there is no estimate ("oscillatory", "at round-off", ...)
};

/// The divergence verdicts of a singular row (flat punch), two of them:
///   eq47: the study's Eq. 47, |s_C - s_M| < |s_M - s_F|;
///   monotone: the magnitudes grow strictly, |s_C| < |s_M| < |s_F|, with one sign;
///   exponent: the mean observed growth exponent alpha of |s| ~ h^-alpha from the two ratios
///     (a square-root singularity gives alpha = 1/2);
///   diverges: monotone and alpha in [kDivergenceExponentMin, kDivergenceExponentMax].
struct DivergenceVerdict {
  bool eq47 = false;
  bool monotone = false;
  std::optional<double> exponent;
  bool diverges = false;
};
inline constexpr double kDivergenceExponentMin = 0.25;
inline constexpr double kDivergenceExponentMax = 0.75;

/// Both verdicts from the values of a singular quantity on C, M, F (h halving per level):
///   eq47 = |s_C - s_M| < |s_M - s_F|;
///   alpha = (log2(s_M/s_C) + log2(s_F/s_M)) / 2 when the three have one sign;
///   diverges = (|s_C| < |s_M| < |s_F|, one sign) and alpha in [0.25, 0.75].
DivergenceVerdict divergence_verdict(double s_c, double s_m, double s_f);

/// What the fourth mesh (VF, h/8, beyond the study) adds to a row: its value and error, the
/// observed order of the error from F to VF, and the verdicts over M, F, VF, to set beside the
/// row's C-M-F verdicts. The row's grade stays the F grade (Table 2's mesh).
struct RefinementVerdict {
  std::optional<double> value;       ///< on VF (empty: case failed)
  std::optional<double> error;       ///< percent, on VF (nonsingular rows)
  std::optional<double> pair_order;  ///< F->VF: log2(|e_F| / |e_VF|), as RowVerdict::pair_orders
  std::optional<bool> converging;    ///< nonsingular: the converging verdict over M, F, VF
  std::optional<bool> diverging;     ///< singular: Eq. 47 over M, F, VF
  std::optional<ErrorEstimate> estimate;        ///< nonsingular: from M, F, VF
  std::optional<DivergenceVerdict> divergence;  ///< singular: from M, F, VF
};

/// One row: the cases of an option set that differ only in mesh level, for one quantity. The
/// study's meshes C, M, F are indexed 0..2 in `values` and `errors`; VF is in `refinement`.
struct RowVerdict {
  std::string id;  ///< case_key(spec) + "/" + quantity, e.g. "H_p/Q4/LMP/ss/sigma_c"
  CaseSpec spec;   ///< the option set (spec.mesh is meaningless here and left at C)
  Quantity quantity = Quantity::sigma_c;
  std::array<std::optional<double>, 3> values;  ///< C, M, F (empty: case missing or failed)
  std::array<std::optional<double>, 3> errors;  ///< percent, C, M, F
  std::optional<Grade> grade;                   ///< of the finest mesh present
  std::optional<MeshLevel> graded_mesh;         ///< which mesh the grade is of
  std::optional<bool> converging;               ///< nonsingular, all three meshes present
  std::optional<bool> diverging;                ///< singular, all three meshes present (Eq. 47)
  /// Observed orders of the error per mesh pair (C->M, M->F): log2(|e_coarse| / |e_fine|);
  /// empty where an error is at round-off (below kErrorNoiseFloorPercent) or missing.
  std::array<std::optional<double>, 2> pair_orders;
  std::optional<ErrorEstimate> estimate;        ///< nonsingular rows with three meshes
  std::optional<DivergenceVerdict> divergence;  ///< singular rows with three meshes
  std::optional<RefinementVerdict> refinement;  ///< rows that have a VF case

  /// True for the study's option sets (see CaseResult::is_baseline).
  bool is_baseline() const;
};

}  // namespace cs::schema

#pragma once
// The study's unit of assessment: one quantity of one problem with one option set, on the
// C, M and F meshes; graded on the finest mesh present (Table 2) and checked for convergence
// or, for the singular problems, divergence (Eq. 47). Assembled by suites/ with the rules of
// grading/, recorded in results.json, read by the gate and the report.

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

/// Error estimate of a nonsingular row from its three meshes (grading/richardson.hpp computes
/// it): the observed order of the value differences, the Richardson limit and Roache's grid
/// convergence index of the fine value. `asymptotic` is false, and the estimate left out, when
/// the sequence is oscillatory or diverging or its differences are at round-off.
struct ErrorEstimate {
  bool asymptotic = false;
  std::optional<double> observed_order{};
  std::optional<double> richardson{};
  std::optional<double> gci_percent{};
  std::string note;  ///< why there is no estimate ("oscillatory", "at round-off", ...)
};

/// The divergence verdicts of a singular row (flat punch), computed by grading/divergence.hpp:
///   eq47: the study's Eq. 47;
///   monotone: the magnitudes grow strictly, with one sign;
///   exponent: the mean observed growth exponent alpha of |s| ~ h^-alpha;
///   diverges: the strict verdict (monotone, alpha near the square-root singularity's 1/2).
struct DivergenceVerdict {
  bool eq47 = false;
  bool monotone = false;
  std::optional<double> exponent;
  bool diverges = false;
};

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
  /// Observed orders of the error per mesh pair (C->M, M->F), grading::pair_order:
  /// log2(|e_coarse| / |e_fine|); empty where an error is at round-off or missing.
  std::array<std::optional<double>, 2> pair_orders;
  std::optional<ErrorEstimate> estimate;        ///< nonsingular rows with three meshes
  std::optional<DivergenceVerdict> divergence;  ///< singular rows with three meshes
  std::optional<RefinementVerdict> refinement;  ///< rows that have a VF case

  /// True for the study's option sets (see CaseResult::is_baseline).
  bool is_baseline() const;
};

}  // namespace cs::schema

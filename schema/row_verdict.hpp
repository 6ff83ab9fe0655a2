#pragma once
// The study's unit of assessment: one quantity of one problem with one option set, on the
// C, M and F meshes; graded on the finest mesh present (Table 2) and checked for convergence
// or, for the singular problems, divergence (Eq. 47). Computed by suites/ (the grading rules),
// recorded in results.json, read by the gate and the report.

#include <array>
#include <optional>
#include <string>

#include "schema/case_spec.hpp"
#include "schema/grade.hpp"
#include "schema/quantity.hpp"

namespace cs::schema {

/// One row: the cases of an option set that differ only in mesh level, for one quantity.
struct RowVerdict {
  std::string id;  ///< case_key(spec) + "/" + quantity, e.g. "H_p/Q4/LMP/ss/sigma_c"
  CaseSpec spec;   ///< the option set (spec.mesh is meaningless here and left at C)
  Quantity quantity = Quantity::sigma_c;
  std::array<std::optional<double>, 3> values;  ///< C, M, F (empty: case missing or failed)
  std::array<std::optional<double>, 3> errors;  ///< percent, C, M, F
  std::optional<Grade> grade;                   ///< of the finest mesh present
  std::optional<MeshLevel> graded_mesh;         ///< which mesh the grade is of
  std::optional<bool> converging;               ///< nonsingular, all three meshes present
  std::optional<bool> diverging;                ///< singular, all three meshes present

  /// True for the study's option sets (see CaseResult::is_baseline).
  bool is_baseline() const;
};

}  // namespace cs::schema

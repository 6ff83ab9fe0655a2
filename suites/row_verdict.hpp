#pragma once
// The study's unit of assessment: one quantity of one problem with one option set, on the
// C, M and F meshes; graded on the fine mesh (Table 2) and checked for convergence or, for
// the singular problems, divergence (Eq. 47).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "suites/case_result.hpp"

namespace cs::suites {

/// One row: a (problem, element, algorithm, contact, target, recovery, overrides, quantity) over
/// meshes.
struct RowVerdict {
  std::string id;  ///< "H_p/Q4/LMP/ss/sigma_c" (+ "/rigid", overrides): the case id less the mesh
  ProblemId problem = ProblemId::P_p;
  ElementType element = ElementType::Q4;
  Algorithm algorithm = Algorithm::LMP;
  ContactKind contact = ContactKind::ss;
  TargetKind target = TargetKind::Discretized;
  Recovery recovery = Recovery::spr;
  std::string quantity;
  std::array<std::optional<double>, 3> values;  ///< C, M, F (empty: case missing or failed)
  std::array<std::optional<double>, 3> errors;  ///< percent, C, M, F
  std::optional<Grade> grade;                   ///< of the finest mesh present
  std::optional<MeshLevel> graded_mesh;         ///< which mesh the grade is of
  std::optional<bool> converging;               ///< nonsingular, all three meshes present
  std::optional<bool> diverging;                ///< singular, all three meshes present
};

/// Groups the cases into rows (cases that differ only in mesh level) and applies the verdicts.
/// Cases with status `failed` leave their mesh empty in the row.
std::vector<RowVerdict> make_row_verdicts(const std::vector<CaseResult>& cases);

}  // namespace cs::suites

#pragma once
// One analysis of the battery: its value on every case axis (schema/case_axes.hpp) and any
// parameter overrides, and its stable identifier.

#include <map>
#include <string>
#include <string_view>

#include "schema/case_axes.hpp"

namespace cs::schema {

/// One analysis. `overrides` holds `--set name=value` pairs, validated by the problem.
struct CaseSpec {
  ProblemId problem = ProblemId::P_p;
  MeshLevel mesh = MeshLevel::C;
  Element element = Element::Q4;
  Algorithm algorithm = Algorithm::LMP;
  ContactKind contact = ContactKind::ss;
  TargetKind target = TargetKind::Discretized;
  Recovery recovery = Recovery::spr;
  SolverKind solver = SolverKind::builtin;
  /// The name of the code for imported results (e.g. "abaqus-2024") and external codes
  /// ("getfem"); empty otherwise.
  std::string solver_name{};
  /// An external code's own option label (e.g. "nitsche"); empty otherwise. The algorithm and
  /// contact fields then hold the option's family and discretization as the manifest states.
  std::string solver_option{};
  std::map<std::string, double> overrides{};

  friend bool operator==(const CaseSpec&, const CaseSpec&) = default;
};

/// The solver as results.json and the report name it: "builtin", the imported code's own name,
/// or a registered code's "<name>:<option>" (e.g. "getfem:nitsche", "calculix:hard-ss").
std::string solver_label(const CaseSpec& spec);

/// A stable identifier of a case: "H_p/F/Q4/LMP/ss" (+ "/rigid", "/extrapolated", "/k=v"
/// overrides, and "/@<name>" (imported) or "/@<name>:<option>" (a registered code, e.g.
/// "/@calculix:hard-ss") for a solver other than ours).
std::string case_id(const CaseSpec& spec);

/// The case a case id names: the inverse of case_id() on its canonical form. The five fields
/// problem/mesh/element/algorithm/contact, then in case_id()'s order "rigid", a recovery other
/// than spr, "name=value" overrides (sorted by name) and "@<solver>" ("@<code>:<option>" for a
/// registered code, any other name for imported results, recorded in solver_name; "@calculix"
/// alone, version 3's suffix, is refused: CalculiX's cases name their option). Throws SchemaError
/// naming the id and its first bad field; an id that parses but is not written as case_id() writes
/// it (an alias, a reordered or repeated field, "fkn=10.0" for "fkn=10") is refused with the
/// canonical form, so that one case has one id. Parameters are not validated here
/// (suites::validate_case does).
CaseSpec parse_case_id(std::string_view id);

/// True for the study's option sets: our solver, a discretized target, patch-recovered nodal
/// stresses and no parameter overrides (the "baseline" rows of the report).
bool is_baseline(const CaseSpec& spec);

/// The case id less its mesh field: "H_p/Q4/LMP/ss" (the key of a row, without quantity).
std::string case_key(const CaseSpec& spec);

}  // namespace cs::schema

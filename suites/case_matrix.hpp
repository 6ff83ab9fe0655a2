#pragma once
// The study's case matrix, or any subset of it: the product of the selected values of each
// axis, in the study's order (problem, mesh, element, algorithm, contact, then recovery).

#include <map>
#include <string>
#include <vector>

#include "suites/case_spec.hpp"
#include "suites/parameter_sweep.hpp"

namespace cs::suites {

/// Which values of each axis to run. Empty lists mean "all the study's values" (for contacts:
/// ss and ns; mortar only when asked for; for problems: the study's eleven, the problems beyond
/// it only when named; for algorithms: all five, but no MPC for a friction problem).
struct CaseSelection {
  std::vector<ProblemId> problems;
  std::vector<MeshLevel> meshes;
  std::vector<Element> elements;
  std::vector<Algorithm> algorithms;
  std::vector<ContactKind> contacts;
  TargetKind target = TargetKind::Discretized;
  SolverKind solver = SolverKind::builtin;  ///< who solves every case (imported: see `grade`)
  /// Nodal stress recoveries: each case once per recovery (empty: spr only). They share the
  /// model and its factorization.
  std::vector<Recovery> recoveries;
  std::map<std::string, double> overrides;  ///< applied to every case
  /// Swept parameters: each case once per point of their cross product (innermost axis), the
  /// point's values added to its overrides. Cases that differ only in contact-only keys (fkn,
  /// ftoln, pinball) share one model; the others split it (suites/runner.hpp).
  std::vector<SweepAxis> sweeps;
};

/// Expands a selection into cases; duplicates in a list are ignored. Throws SuiteInputError
/// for a sweep validate_sweeps refuses.
std::vector<CaseSpec> make_case_matrix(const CaseSelection& selection);

}  // namespace cs::suites

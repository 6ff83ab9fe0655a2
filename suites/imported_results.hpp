#pragma once
// Grading another code's results (`contact-suite grade --import FILE --solver-name NAME`): each
// case id of the import file (suites/import_csv.hpp) is rebuilt as the case it names
// (build_problem, once per model), its rows are matched to the nodes of the sampled surface, and
// the quantities are sampled by sample_quantities() exactly as for the built-in solver and
// CalculiX, so a quantity means the same for every solver. The cases' solver is
// SolverKind::imported with solver_name NAME (case ids end in "/@NAME"), or, for a case whose
// rows give the code's own option label, the code and its option as a registered code's cases
// are named (SolverKind::external, "/@NAME:LABEL"; its algorithm and contact fields are the
// study column and discretization the id names).
//
// Target and stress basis: what the case id says ("/rigid", "/own"), or what the command line
// states for every case (ImportBasis: --target, --recovery); an id that says otherwise than the
// command line is refused. The optional per-case columns (wall time, iterations, equations,
// peak memory) are recorded as the case's own.
//
// What is refused, as bad input naming the file and line (SuiteInputError): a solver name that
// is empty, longer than 64 characters, outside [A-Za-z0-9._-], a built-in solver's name or a
// registered code's (CalculiX, GetFEM, any manifest's: their results would be taken for it); a
// case id that does not name a case of the catalogue (unknown names, a solver suffix, a bad
// parameter, friction, IF_p and IF_a) or whose target or basis contradicts the command line; a
// row whose x is no node of the sampled surface (within 1e-3 of the smallest node spacing), two
// rows on one node, and a surface node without a row. Every imported case is `converged`, with
// the iterations, time, equations and memory its optional columns give (0 where they give none).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "suites/case_result.hpp"
#include "suites/import_csv.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// The target and stress basis the command line states for every imported case (none: as each
/// case id says).
struct ImportBasis {
  std::optional<TargetKind> target;
  std::optional<Recovery> recovery;
};

/// Throws SuiteInputError unless `name` can name imported results (see the file comment):
/// `registered` holds the names of the registered codes (adapters::registered_codes), which
/// imported results must not take.
void require_imported_solver_name(std::string_view name,
                                  const std::vector<std::string>& registered);

/// The case `imported.case_id` names, solved by `solver_name`, on `basis`; throws
/// SuiteInputError "<source>:<line>: unknown case id '...': <why>" for an id outside the
/// catalogue, "<source>:<line>: case '...' ..." for one that contradicts `basis`.
CaseSpec imported_case_spec(const ImportedCase& imported, std::string_view solver_name,
                            std::string_view source_name, const ImportBasis& basis = {});

/// Grades one imported case on its built setup. Throws SuiteInputError (naming the source and
/// line) when the rows do not match the nodes of the sampled surface one to one.
CaseResult grade_imported_case(const ProblemSetup& setup, const CaseSpec& spec,
                               const ImportedCase& imported, std::string_view source_name);

/// Grades every case of an import file (ids checked first, then each model built once), in the
/// file's order of first appearance. Throws SuiteInputError as above.
std::vector<CaseResult> grade_imported(const std::vector<ImportedCase>& cases,
                                       std::string_view solver_name, std::string_view source_name,
                                       const ImportBasis& basis = {});

}  // namespace cs::suites

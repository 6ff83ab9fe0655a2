#pragma once
// The flat-punch divergence table: for the singular problems, per element and option set, the
// edge stress on C, M, F with the two verdicts of grading/divergence.hpp (the study's Eq. 47 and
// the strict one), ours from the row facts, beside the study's ANSYS values and their verdicts.

#include <array>
#include <optional>
#include <string>

#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// Why a strict verdict fails, in words ("tensile", "shrinking", "not monotone",
/// "grows at α 0.05 per halving of h, outside [...]"); empty when it diverges.
std::string strict_failure_reason(const std::array<std::optional<double>, 3>& values,
                                  const schema::DivergenceVerdict& d);

/// The table and its counts.
struct DivergenceTableFacts {
  MarkdownTable table{{}};
  int eq47 = 0, eq47_fails = 0, undecided = 0;  ///< ours, by Eq. 47 (undecided: not C, M, F)
  int strict = 0, strict_fails = 0, eq47_only = 0;
  int fine_not_converged = 0;  ///< rows whose F case did not converge (values: last iterate)
  int not_credible = 0;        ///< rows whose F case fails an interface check (✗)
  int not_credible_eq47 = 0;   ///< of them, those that pass Eq. 47 all the same
  int study_strict_fails = 0;  ///< ANSYS's values failing the strict verdict
};

/// The rows of the singular problems present in the results (table empty: none).
DivergenceTableFacts build_divergence_table(const ResultsIndex& index,
                                            const schema::StudyReference& study);

/// The report section (empty when no case of a singular problem was run).
std::string divergence_section(const ResultsIndex& index, const schema::StudyReference& study);

}  // namespace cs::reports

#pragma once
// The flat-punch divergence table: for F_p and F_a, per element and option set, the edge
// stress on C, M, F with two verdicts (grading::divergence_verdict): the study's Eq. 47,
// |s_C - s_M| < |s_M - s_F|, and the strict one, monotone growth of one sign at a rate alpha
// (|s| ~ h^-alpha) near the square-root singularity's 1/2; beside the study's ANSYS values
// with both verdicts applied to them.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/results/study_reference.hpp"

namespace cs::reports {

/// One row of the divergence table.
struct DivergenceRow {
  schema::ProblemId problem = schema::ProblemId::F_p;
  schema::Element element = schema::Element::Q4;
  Option option;
  std::array<std::optional<double>, 3> values;  ///< ours, C M F
  std::optional<bool> diverging;                ///< ours, from the results file's row verdict
  std::optional<schema::DivergenceVerdict> divergence;        ///< ours, both verdicts
  std::array<std::optional<double>, 3> study_values;          ///< ANSYS, C M F
  std::optional<bool> study_diverging;                        ///< Eq. 47 on the ANSYS values
  std::optional<schema::DivergenceVerdict> study_divergence;  ///< both verdicts on ANSYS's
};

/// Why a strict verdict fails, in words ("tensile", "shrinking", "not monotone",
/// "grows too slowly (α 0.05)"); empty when it diverges.
std::string strict_failure_reason(const std::array<std::optional<double>, 3>& values,
                                  const schema::DivergenceVerdict& d);

/// The rows of the singular problems (F_p, F_a) present in the results, in the study's order.
std::vector<DivergenceRow> build_divergence_rows(const ResultsIndex& index,
                                                 const StudyReference& study);

/// The report section (empty when no case of a singular problem was run).
std::string divergence_section(const ResultsIndex& index, const StudyReference& study);

}  // namespace cs::reports

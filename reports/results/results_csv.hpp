#pragma once
// DIR/results.csv: one row per case and quantity (a case without quantities, e.g. a failed
// one, still gets one row), for spreadsheets; with the study's ANSYS value for the same
// option set where it printed one, and the verdicts of the row the case belongs to (every mesh
// of a row repeats them): the study's convergence flag `converging`, the noise-aware `trend`
// (grading::assess_convergence), and for a singular problem `eq47` and `strict_divergence`
// (grading::divergence_verdict); empty where they do not apply.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// One CSV field, quoted as RFC 4180 asks when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

/// The whole CSV text (RFC 4180 quoting; numbers with 10 significant digits; empty = none).
std::string results_csv(const ResultsIndex& index, const schema::StudyReference& study);

}  // namespace cs::reports

#pragma once
// Section 1 of the report: what was run (cases, problems, meshes, options, machine, date,
// versions — from `run` and `run.environment`), how long it took, how many cases converged,
// did not converge or failed (each of the latter listed with its reason), and the findings.

#include <string>
#include <vector>

#include "reports/findings/findings.hpp"
#include "reports/results/results_index.hpp"

namespace cs::reports {

/// Case counts by status (a case that timed out counts as failed: it has no values either).
struct StatusCounts {
  int converged = 0, not_converged = 0, failed = 0;
  int total() const { return converged + not_converged + failed; }
};

StatusCounts count_statuses(const schema::ResultsDocument& results);

/// The environment object flattened to "solver.factorization" -> "CHOLMOD supernodal" pairs.
std::vector<std::pair<std::string, std::string>> flatten_environment(const nlohmann::json& env);

/// The Markdown of section 1.
std::string summary_section(const ResultsIndex& index, const std::vector<Finding>& findings);

}  // namespace cs::reports

#pragma once
// The cost of each solver on the same cases: the cases of the document that our solver and
// another solver both ran (matched by same_case_key: problem, mesh, element, algorithm,
// contact, target and overrides alike), per problem and mesh and over all of them:
//   wall time  the sum of the cases' wall_seconds, and the ratio other / ours;
//   memory     the largest peak_rss_mb of the cases, and the ratio other / ours.
// Every case of a pair counts, whatever its status (a timeout counts with the time it took);
// the totals are also given over the pairs where both solvers converged.

#include <optional>
#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {

/// The cost of a set of matched cases.
struct CostLine {
  std::string label;  ///< "H<sub>p</sub> F", or "all cases"
  int pairs = 0;
  double ours_seconds = 0.0, other_seconds = 0.0;
  double ours_peak_mb = 0.0, other_peak_mb = 0.0;
  int other_converged = 0;  ///< pairs where the other solver converged

  /// other / ours, or nullopt when ours is 0.
  std::optional<double> time_ratio() const;
  std::optional<double> memory_ratio() const;
};

/// The comparison of one other solver with ours.
struct CrossCodeCost {
  std::string solver;             ///< the other solver's label
  std::vector<CostLine> lines;    ///< per problem and mesh, in the report's order
  CostLine total;                 ///< every pair
  CostLine total_both_converged;  ///< the pairs where both converged
};

/// The comparison as a table: a row per line, then the two totals.
MarkdownTable cost_table(const CrossCodeCost& cost);

/// One comparison per solver other than ours that shares cases with ours (none: empty).
std::vector<CrossCodeCost> cross_code_cost(const ResultsIndex& index);

}  // namespace cs::reports

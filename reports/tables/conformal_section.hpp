#pragma once
// Conformal contact (the problems grading p_mean: the interference fits IF_p, IF_a): per option
// on the fine mesh, the mean contact pressure's error and the largest deviation of the pressure
// along the arc (the error of p_arc), and which option resolves the arc best and worst.

#include <optional>
#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The option of a problem with the largest (or smallest) |deviation along the arc| on F.
struct ArcExtreme {
  double deviation_percent = 0.0;  ///< signed, the error of p_arc on F
  schema::Element element = schema::Element::Q4;
  Option option;
};

/// The worst and the best option of `problem` by |p_arc error| on F (nullopt: no row on F).
std::optional<ArcExtreme> worst_arc_option(const ResultsIndex& index, schema::ProblemId problem);
std::optional<ArcExtreme> best_arc_option(const ResultsIndex& index, schema::ProblemId problem);

/// The section (empty when the results hold no baseline row of a conformal problem).
std::string conformal_section(const ResultsIndex& index);

}  // namespace cs::reports

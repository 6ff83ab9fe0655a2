#pragma once
// Conformal contact (the problems grading p_mean: the interference fits IF_p, IF_a): per option
// on the fine mesh, the mean contact pressure's error and the largest deviation of the pressure
// along the arc (the error of p_arc), and which option resolves the arc best and worst.

#include <optional>
#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// An option of a problem and its deviation along the arc on F.
struct ArcExtreme {
  double deviation_percent = 0.0;  ///< signed, the error of p_arc on F
  schema::Element element = schema::Element::Q4;
  Option option;
};

/// The options of a problem with the smallest (best) and the largest (worst) |p_arc error| on F.
struct ArcRange {
  ArcExtreme best, worst;
};

/// The arc range of `problem` (nullopt: no p_arc row on F).
std::optional<ArcRange> arc_range(const ResultsIndex& index, schema::ProblemId problem);

/// The section (empty when the results hold no baseline row of a conformal problem).
std::string conformal_section(const ResultsIndex& index);

}  // namespace cs::reports

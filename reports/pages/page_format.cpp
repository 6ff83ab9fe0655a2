#include "reports/pages/page_format.hpp"

#include <cmath>

#include <fmt/format.h>

#include "reports/facts/solvers.hpp"

namespace cs::reports {

std::string format_points(double points) {
  const double p = std::abs(points);
  if (p == 0.0)
    return "0 points";
  return fmt::format("{:.2g} points", p);
}

std::string format_measure(double measure) {
  return fmt::format("{:.3g}", measure);
}

std::string solver_names(const ResultsIndex& index, const char* last) {
  std::vector<std::string> names;
  for (const auto& s : solvers_in(index))
    names.push_back(solver_display_name(s));
  return join_words(names, last);
}

}  // namespace cs::reports

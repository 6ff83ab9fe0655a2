#include "reports/pages/page_format.hpp"

#include <cmath>
#include <set>

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

std::string recovery_names(const ResultsIndex& index) {
  std::set<schema::Recovery> used;
  for (const auto& c : index.results().cases)
    used.insert(c.spec.recovery);
  std::string out;
  for (const auto r : used) {
    out += out.empty() ? "" : " and ";
    out += r == schema::Recovery::spr ? "patch-recovered nodal stresses (SPR)"
                                      : "extrapolated nodal stresses (as ANSYS prints them)";
  }
  return out;
}

}  // namespace cs::reports

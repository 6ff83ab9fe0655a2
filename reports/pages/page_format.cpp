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

std::string solver_names(const ResultsIndex& index) {
  const auto solvers = solvers_in(index);
  std::string out;
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const char* sep = i == 0 ? "" : (i + 1 == solvers.size() ? " and " : ", ");
    out += sep + solver_display_name(solvers[i]);
  }
  return out;
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

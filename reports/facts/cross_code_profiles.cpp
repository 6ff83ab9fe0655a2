#include "reports/facts/cross_code_profiles.hpp"

#include <fmt/format.h>

#include "reports/tables/cross_code_rows.hpp"

namespace cs::reports {
namespace {

using schema::ProblemId;

/// The fine-mesh case of a solver's row of (problem, element, option), or nullptr.
const schema::CaseResult* fine_case(const ResultsIndex& index, const std::string& solver,
                                    const schema::ProblemRecord& p, schema::Element element,
                                    const Option& o) {
  for (const auto& q : p.quantities) {
    if (const auto* row = solver_row(index, solver, p.id, q.quantity, element, o))
      return index.case_of(*row, kFinestMesh);
  }
  return nullptr;
}

bool has_pressure(const schema::CaseResult* c) {
  return c != nullptr && c->status == schema::CaseStatus::converged &&
         !c->profile.pressure_over_p.empty();
}

/// The option set of a panel (see the header), or nullopt when no other solver ran one.
std::optional<Option> panel_option(const ResultsIndex& index, const schema::ProblemRecord& p,
                                   schema::Element element,
                                   const std::vector<std::string>& solvers) {
  std::optional<Option> fallback;
  for (const auto& o : all_options()) {
    bool other = false, all = true;
    for (const auto& s : solvers) {
      const auto* c = fine_case(index, s, p, element, o);
      other = other || (s != builtin_solver_label() && c != nullptr);
      all = all && has_pressure(c);
    }
    if (other && all)
      return o;
    if (other && !fallback)
      fallback = o;
  }
  return fallback;
}

CrossCodePanel make_panel(const ResultsIndex& index, const schema::ProblemRecord& p,
                          schema::Element element, const Option& o,
                          const std::vector<std::string>& solvers) {
  CrossCodePanel panel{p.id, element, o, {}, {}};
  const schema::ExactProfile* exact = nullptr;
  for (const auto& s : solvers) {
    const auto* c = fine_case(index, s, p, element, o);
    if (!has_pressure(c)) {
      panel.missing.push_back(fmt::format("{} ({})", solver_display_name(s),
                                          c == nullptr ? "not run" : schema::label(c->status)));
      continue;
    }
    ProfileCurve curve{solver_display_name(s), {}};
    const auto& pr = c->profile;
    for (std::size_t i = 0; i < pr.x_over_a.size() && i < pr.pressure_over_p.size(); ++i)
      curve.xy.emplace_back(pr.x_over_a[i], pr.pressure_over_p[i]);
    panel.curves.push_back(std::move(curve));
    if (exact == nullptr && !c->exact_profile.empty())
      exact = &c->exact_profile;
  }
  if (exact != nullptr) {
    ProfileCurve curve{"exact", {}};
    for (std::size_t i = 0; i < exact->x_over_a.size() && i < exact->sigma_z_over_p.size(); ++i)
      curve.xy.emplace_back(exact->x_over_a[i], exact->sigma_z_over_p[i]);
    panel.curves.push_back(std::move(curve));
  }
  return panel;
}

}  // namespace

std::vector<ProblemId> cross_code_figure_problems() {
  return {ProblemId::H_p, ProblemId::S_1_3};
}

std::vector<CrossCodePanel> cross_code_profile_panels(const ResultsIndex& index) {
  std::vector<CrossCodePanel> out;
  const auto solvers = solvers_in(index);
  for (const ProblemId id : cross_code_figure_problems()) {
    const schema::ProblemRecord* p = index.problem(id);
    if (p == nullptr)
      continue;
    for (const auto element : schema::values<schema::Element>()) {
      if (const auto o = panel_option(index, *p, element, solvers))
        out.push_back(make_panel(index, *p, element, *o, solvers));
    }
  }
  return out;
}

}  // namespace cs::reports

#include "reports/figures/figures.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "reports/figures/gnuplot.hpp"

namespace cs::reports {

schema::LengthScale length_scale_of(const ResultsIndex& index, schema::ProblemId id) {
  const schema::ProblemRecord* p = index.problem(id);
  return p != nullptr && p->length_scale ? *p->length_scale
                                         : schema::LengthScale::contact_half_width_a;
}

std::string option_colour(const Option& option) {
  const auto& all = all_options();
  return palette_colour(
      static_cast<std::size_t>(std::find(all.begin(), all.end(), option) - all.begin()));
}

FigureSet render_figures(const ResultsIndex& index, const std::filesystem::path& out_root,
                         const FigureOptions& options) {
  std::vector<Plot> plots;  // drawn at once below, plots[i] into figures[i]
  std::vector<Figure> figures;
  const auto add = [&](Plot&& plot, Figure&& figure) {
    if (plot.panels.empty())
      return;
    plots.push_back(std::move(plot));
    figures.push_back(std::move(figure));
  };
  for (const schema::ProblemRecord* p : index.problems()) {
    // The profile is -sigma_z/p along a flat contact surface z = 0 (the study's Figure 4); a
    // fit's contact is an arc, graded by p_mean and p_arc: it has none.
    if (p->situation == schema::Situation::conformal_fit)
      continue;
    for (const auto element : schema::values<schema::Element>()) {
      Figure f(FigureKind::profile,
               fmt::format("figures/profile_{}_{}.png", schema::to_string(p->id),
                           schema::to_string(element)),
               p->id);
      add(profile_plot(index, p->id, element, f), std::move(f));
    }
  }
  const std::vector<RowFacts> rows = row_facts(index);
  const std::vector<DivergenceFacts> singular = divergence_facts(index);
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      Figure f(FigureKind::convergence,
               fmt::format("figures/convergence_{}_{}.png", schema::to_string(p->id),
                           schema::to_string(q.quantity)),
               p->id);
      add(convergence_plot(index, rows, singular, *p, q, f), std::move(f));
    }
  }
  return draw_figures(plots, std::move(figures), out_root, options);
}

}  // namespace cs::reports

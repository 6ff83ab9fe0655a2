// The convergence figure (figures/figures.hpp): error (or the singular value) against h.

#include <algorithm>
#include <cmath>
#include <ranges>

#include <fmt/format.h>

#include "reports/figures/figures.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {
namespace {

/// What the legend says of a row: the guarded observed order (grading::observed_order, through
/// RowFacts) or why there is none; for a singular row, its divergence exponent.
std::string order_legend(const schema::RowVerdict* row, const std::vector<RowFacts>& rows,
                         const std::vector<DivergenceFacts>& singular) {
  for (const auto& d : singular) {
    if (d.row == row)
      return d.exponent ? fmt::format("exponent {:.2f}", *d.exponent) : "no exponent";
  }
  for (const auto& f : rows) {
    if (f.row != row)
      continue;
    if (f.order)
      return fmt::format("order {:.2f}", *f.order);
    if (f.biased_limit)
      return fmt::format("to a limit of {}", format_error_resolved(f.biased_limit->error_percent));
    return "no order: " + f.order_note.substr(0, f.order_note.find(" ("));
  }
  return "no order: no F value";
}

/// Grey reference lines through the median curve's coarsest point: slopes 1 and 2 for an
/// error, -1/2 (a square-root singularity's growth) for a singular value.
void add_reference_slopes(PlotPanel& panel, bool singular) {
  const Points all = points_of(panel);
  if (all.empty())
    return;
  const auto [lo, hi] = std::ranges::minmax(all | std::views::keys);
  std::vector<double> start;
  for (const auto& [x, y] : all) {
    if (x >= hi * (1 - 1e-9))
      start.push_back(y);
  }
  if (!(hi > lo) || !(lo > 0))
    return;
  std::ranges::sort(start);
  const double y0 = start[start.size() / 2];
  for (const double slope : singular ? std::vector{-0.5} : std::vector{1.0, 2.0}) {
    panel.series.push_back(line_series(fmt::format("slope {:g}", slope), "#999999",
                                       {{hi, y0}, {lo, y0 * std::pow(lo / hi, slope)}}, 4, 1.0));
  }
}

}  // namespace

Plot convergence_plot(const ResultsIndex& index, const std::vector<RowFacts>& rows,
                      const std::vector<DivergenceFacts>& singular, const schema::ProblemRecord& p,
                      const schema::QuantityDefinition& q, Figure& figure) {
  Plot plot{.title = fmt::format("{} ({}): {} against element size", schema::label(p.id),
                                 q.definition_plain, p.singular ? "edge stress" : "|error|"),
            .panel_width = 700,
            .panel_height = 480};
  bool relative = false, round_off = false;
  for (const auto element : schema::values<schema::Element>()) {
    if (!index.has(p.id, q.quantity, element))
      continue;
    const Slot slot{p.id, q.quantity, element};
    PlotPanel panel{
        name_of(element),
        {fmt::format("element size h / {}", schema::symbol(length_scale_of(index, p.id))),
         Scale::log},
        {p.singular ? q.definition_plain : "|error| (%)", Scale::log}};
    for (const auto& cls : coincidence_classes(index, all_options(), {slot})) {
      const schema::RowVerdict* row = class_row(index, cls, slot);
      const auto& contact = schema::traits(cls.members.front().contact);
      PlotSeries s{cls.label() + ": " + order_legend(row, rows, singular),
                   option_colour(cls.members.front()), Mark::line_points, contact.dash,
                   contact.point};
      for (std::size_t m = 0; m < kMeshes.size(); ++m) {
        const schema::CaseResult* c = index.case_of(*row, kMeshes[m]);
        const auto y = p.singular ? row->values[m] : row->errors[m];
        const double h = c ? finite(c->element_size_h).value_or(0.0) : 0.0;  // 0: not known
        relative = relative || (y && !(h > 0));
        if (y && std::abs(*y) < schema::kErrorNoiseFloorPercent)
          round_off = true;  // exact to round-off: nothing to draw on a log scale
        else if (y && std::isfinite(*y))
          s.xy.emplace_back(h > 0 ? h : std::ldexp(1.0, -static_cast<int>(m)), std::abs(*y));
      }
      panel.series.push_back(std::move(s));
    }
    for (const auto& [x, y] : points_of(panel)) {
      if (std::ranges::none_of(panel.x.tics,
                               [x](const auto& t) { return std::abs(t.first - x) <= 1e-6 * x; }))
        panel.x.tics.emplace_back(x, fmt::format("{:.3g}", x));  // the meshes' sizes
    }
    add_reference_slopes(panel, p.singular);
    plot.panels.push_back(std::move(panel));
  }
  TemplateData caption("problem", std::string(schema::label(p.id)));
  caption.set("quantity", std::string(schema::label(q.quantity)));
  caption.set("singular", p.singular);
  figure.caption_md = figure_text("convergence", caption);
  if (relative)
    figure.notes.push_back(figure_text("relative_h"));
  if (round_off)
    figure.notes.push_back(figure_text(
        "round_off", TemplateData("floor", fmt::format("{:g}", schema::kErrorNoiseFloorPercent))));
  return plot;
}

}  // namespace cs::reports

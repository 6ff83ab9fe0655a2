#include "reports/figures/bench_figure.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/figures/gnuplot.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// Gap between clusters of bars, in bar widths.
constexpr double kGap = 1.0;

/// One panel: bars of the algorithms (one colour each) clustered by discretization, the ratio
/// above each bar ('*': not converged), the reference time and the target's limit as lines.
PlotPanel bar_panel(const BenchGrid& grid, double max_ratio) {
  const auto& [model, cases, contacts, methods] = grid;
  double top = 0;
  PlotPanel panel{model_md(model), {""}, {"time (ms)"}};
  const double n = static_cast<double>(methods.size());
  panel.bar_width = 1.0 / (n + kGap);
  for (std::size_t j = 0; j < methods.size(); ++j) {
    PlotSeries bars{name_of(methods[j]),
                    std::string(schema::traits(study_algorithm(methods[j])).colour), Mark::bars};
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const BenchRow* b = grid.at(contacts[i], methods[j]);
      if (b == nullptr || !b->time_ms)
        continue;
      const double x = static_cast<double>(i) + (static_cast<double>(j) - (n - 1) / 2) / (n + kGap);
      bars.xy.emplace_back(x, *b->time_ms);
      top = std::max(top, *b->time_ms);
      if (b->ratio())
        panel.labels.push_back(
            {x, *b->time_ms, fmt::format("{:.2f}{}", *b->ratio(), b->converged() ? "" : "*")});
    }
    panel.series.push_back(std::move(bars));
  }
  const double right = static_cast<double>(contacts.size()) - 0.5;
  for (std::size_t i = 0; i < contacts.size(); ++i)
    panel.x.tics.emplace_back(static_cast<double>(i), name_of(contacts[i]));
  panel.x.range = std::pair(-0.5, right);
  if (const auto reference = grid.reference_ms()) {
    const double ms = *reference;
    panel.title += fmt::format(": reference {} ms", format_milliseconds(ms));
    top = std::max(top, max_ratio * ms);
    panel.series.push_back(
        line_series("reference (ratio 1)", "#000000", {{-0.5, ms}, {right, ms}}, 2));
    panel.series.push_back(line_series(fmt::format("ratio {:g} (target)", max_ratio), "#d62728",
                                       {{-0.5, max_ratio * ms}, {right, max_ratio * ms}}, 4));
  }
  panel.y.range = std::pair(0.0, top > 0 ? 1.15 * top : 1.0);
  return panel;
}

}  // namespace

FigureSet render_bench_figures(const BenchResults& bench, const std::filesystem::path& out_root,
                               const BenchTarget& target, const FigureOptions& options) {
  // Per problem and element, the finest mesh with a timed case.
  std::map<std::pair<schema::ProblemId, schema::Element>, BenchGrid> finest;
  for (const BenchGrid& grid : contact_grids(bench)) {
    if (std::ranges::any_of(grid.cases, [](const BenchRow* b) { return b->time_ms.has_value(); }))
      finest[{grid.model.problem, grid.model.element}] = grid;
  }
  if (finest.empty())
    return {};
  Plot plot{
      .title = "Time of the contact analysis per algorithm (ratio to the reference above each bar)",
      .panel_width = 620,
      .key_columns = 4};
  std::vector<std::string> models;
  bool any_failed = false;
  for (const auto& [unused, grid] : finest) {
    plot.panels.push_back(bar_panel(grid, target.max_ratio));
    models.push_back(model_md(grid.model));
    any_failed = any_failed ||
                 std::ranges::any_of(grid.cases, [](const BenchRow* b) { return !b->converged(); });
  }
  Figure figure(FigureKind::bench, "figures/bench_time.png");
  TemplateData caption("models", fmt::format("{}", fmt::join(models, "; ")));
  caption.set("target", fmt::format("{:g}", target.max_ratio));
  caption.set("any_failed", any_failed);
  figure.caption_md = figure_text("bench", caption);
  return draw_figures({plot}, {figure}, out_root, options);
}

}  // namespace cs::reports

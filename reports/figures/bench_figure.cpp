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
PlotPanel bar_panel(const std::vector<const BenchRow*>& cases, double max_ratio) {
  const auto [contacts, methods] = options_of(cases);
  const auto reference =
      std::ranges::find_if(cases, [](const BenchRow* b) { return b->reference_ms().has_value(); });
  double top = 0;
  PlotPanel panel{model_md(cases.front()->model), {""}, {"time (ms)"}};
  const double n = static_cast<double>(methods.size());
  panel.bar_width = 1.0 / (n + kGap);
  for (std::size_t j = 0; j < methods.size(); ++j) {
    PlotSeries bars{std::string(schema::to_string(methods[j])),
                    std::string(schema::traits(study_algorithm(methods[j])).colour), Mark::bars};
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const BenchRow* b = find_case(cases, contacts[i], methods[j]);
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
    panel.x.tics.emplace_back(static_cast<double>(i), std::string(schema::to_string(contacts[i])));
  panel.x.range = std::pair(-0.5, right);
  if (reference != cases.end()) {
    const double ms = *(*reference)->reference_ms();
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
  std::map<std::pair<schema::ProblemId, schema::Element>, std::vector<const BenchRow*>> finest;
  for (const auto& cases : by_model(bench.of(BenchFamily::Contact))) {
    if (std::ranges::any_of(cases, [](const BenchRow* b) { return b->time_ms.has_value(); }))
      finest[{cases.front()->model.problem, cases.front()->model.element}] = cases;
  }
  if (finest.empty())
    return {};
  Plot plot{
      .title = "Time of the contact analysis per algorithm (ratio to the reference above each bar)",
      .panel_width = 620,
      .key_columns = 4};
  std::vector<std::string> models;
  bool any_failed = false;
  for (const auto& [unused, cases] : finest) {
    plot.panels.push_back(bar_panel(cases, target.max_ratio));
    models.push_back(model_md(cases.front()->model));
    any_failed = any_failed || std::ranges::any_of(cases, [](auto* b) { return !b->converged(); });
  }
  Figure figure(FigureKind::bench, "figures/bench_time.png");
  TemplateData caption("models", fmt::format("{}", fmt::join(models, "; ")));
  caption.set("target", fmt::format("{:g}", target.max_ratio));
  caption.set("any_failed", any_failed);
  figure.caption_md = figure_text("bench", caption);
  GnuplotWriter writer(options);
  FigureSet set{{}, writer.unavailable()};
  writer.draw(plot, out_root, figure);
  set.figures.push_back(std::move(figure));
  return set;
}

}  // namespace cs::reports

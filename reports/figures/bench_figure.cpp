#include "reports/figures/bench_figure.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::ContactKind;

/// Gap between clusters of bars, in bar widths.
constexpr double kGap = 1.0;

/// One panel: bars of the algorithms (one colour each) clustered by discretization, the ratio
/// above each bar ('*': not converged), the reference time and the target's limit as lines.
PlotPanel bar_panel(const std::vector<const BenchRow*>& cases, double max_ratio) {
  const auto [contacts, methods] = options_of(cases);
  std::optional<double> reference;
  double top = 0;
  PlotPanel panel{model_md(cases.front()->model), {""}, {"time (ms)"}};
  const double n = static_cast<double>(methods.size());
  panel.bar_width = 1.0 / (n + kGap);
  for (std::size_t j = 0; j < methods.size(); ++j) {
    PlotSeries bars{std::string(schema::to_string(methods[j])),
                    std::string(schema::traits(study_algorithm(methods[j])).colour), Mark::bars};
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      for (const auto* b : cases) {
        if (b->contact != contacts[i] || b->algorithm != methods[j] || !b->time_ms)
          continue;
        const double x =
            static_cast<double>(i) + (static_cast<double>(j) - (n - 1) / 2) / (n + kGap);
        bars.xy.emplace_back(x, *b->time_ms);
        top = std::max(top, *b->time_ms);
        reference = reference ? reference : b->reference_ms();
        if (b->ratio())
          panel.labels.push_back(
              {x, *b->time_ms, fmt::format("{:.2f}{}", *b->ratio(), b->converged() ? "" : "*")});
      }
    }
    panel.series.push_back(std::move(bars));
  }
  const double right = static_cast<double>(contacts.size()) - 0.5;
  for (std::size_t i = 0; i < contacts.size(); ++i)
    panel.x.tics.emplace_back(static_cast<double>(i), std::string(schema::to_string(contacts[i])));
  panel.x.range = std::pair(-0.5, right);
  if (reference) {
    panel.title += fmt::format(": reference {} ms", format_milliseconds(*reference));
    top = std::max(top, max_ratio * *reference);
    panel.series.push_back(line_series("reference (ratio 1)", "#000000",
                                       {{-0.5, *reference}, {right, *reference}}, 2));
    panel.series.push_back(
        line_series(fmt::format("ratio {:g} (target)", max_ratio), "#d62728",
                    {{-0.5, max_ratio * *reference}, {right, max_ratio * *reference}}, 4));
  }
  panel.y.range = std::pair(0.0, top > 0 ? 1.15 * top : 1.0);
  return panel;
}

}  // namespace

FigureSet render_bench_figures(const BenchResults& bench, const std::filesystem::path& out_root,
                               const BenchTarget& target, const FigureOptions& options) {
  FigureSet set;
  Plot plot{
      .title = "Time of the contact analysis per algorithm (ratio to the reference above each bar)",
      .panel_width = 620,
      .key_columns = 4};
  std::vector<std::string> models;
  bool any_failed = false;
  for (const auto& cases : finest_models(bench)) {
    plot.panels.push_back(bar_panel(cases, target.max_ratio));
    models.push_back(model_md(cases.front()->model));
    for (const auto* b : cases)
      any_failed = any_failed || !b->converged();
  }
  if (plot.panels.empty())
    return set;
  Figure figure(FigureKind::bench, "figures/bench_time.png");
  TemplateData caption("models", fmt::format("{}", fmt::join(models, "; ")));
  caption.set("target", fmt::format("{:g}", target.max_ratio));
  caption.set("any_failed", any_failed);
  figure.caption_md = figure_text("bench", caption);
  GnuplotWriter writer(options);
  set.unavailable = writer.unavailable();
  writer.draw(plot, out_root, figure);
  set.figures.push_back(std::move(figure));
  return set;
}

}  // namespace cs::reports

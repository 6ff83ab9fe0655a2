#include "reports/figures/sweep_figure.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"
#include "reports/findings/sweep_section.hpp"
#include "reports/render/template_text.hpp"

namespace cs::reports {
namespace {

/// The values span this ratio or more: a log x-axis.
constexpr double kLogSpan = 100.0;

/// The curve of one series: a line through the drawn points, filled symbols where the case
/// converged, open circles where it did not. Returns how many points were left out.
int add_curves(PlotPanel& panel, const ParameterSeries& s) {
  const auto& contact = schema::traits(s.spec.contact);
  const std::string colour = option_colour({s.spec.algorithm, s.spec.contact});
  PlotSeries line{s.option_label(), colour, Mark::line, contact.dash};
  PlotSeries done{"", colour, Mark::points, 1, contact.point},
      failed{"", colour, Mark::open_points};
  int left_out = 0;
  for (const auto& p : s.points) {
    if (!p.error)
      continue;
    if (std::abs(*p.error) < schema::kErrorNoiseFloorPercent) {
      ++left_out;
      continue;
    }
    line.xy.emplace_back(p.parameter, std::abs(*p.error));
    (p.converged() ? done : failed).xy.emplace_back(p.parameter, std::abs(*p.error));
  }
  for (auto* c : {&line, &done, &failed})
    panel.series.push_back(std::move(*c));
  return left_out;
}

}  // namespace

std::vector<SweepPanel> sweep_panels(const std::vector<ParameterSeries>& series) {
  using Key = std::tuple<schema::ProblemId, schema::Quantity, schema::MeshLevel, schema::Element>;
  std::map<Key, std::size_t> slot;
  std::vector<SweepPanel> panels;
  for (const auto& s : series) {
    if (s.quantity == schema::Quantity::contact_half_width || !on_finest_mesh(s, series))
      continue;  // the half-width is graded apart: it moves by whole nodes
    const Key key{s.spec.problem, s.quantity, s.spec.mesh, s.spec.element};
    const auto [it, fresh] = slot.try_emplace(key, panels.size());
    if (fresh)
      panels.push_back({s.spec.problem, s.quantity, s.spec.mesh, s.spec.element, {}});
    panels[it->second].series.push_back(&s);
  }
  return panels;
}

Plot sweep_plot(const schema::ResultsDocument& doc, const std::string& key,
                const std::vector<SweepPanel>& panels, Figure& figure) {
  Plot plot{.title = fmt::format("|error| against {} (open circles: not converged)", key),
            .panels = {},
            .columns = 3,
            .panel_width = 520,
            .panel_height = 400};
  int left_out = 0;
  bool no_default = false;
  for (const auto& p : panels) {
    PlotPanel panel{
        fmt::format("{} {}, mesh {}, {}", schema::label(p.problem), schema::label(p.quantity),
                    schema::to_string(p.mesh), schema::to_string(p.element)),
        {key},
        {"|error| (%)", Scale::log}};
    for (const ParameterSeries* s : p.series)
      left_out += add_curves(panel, *s);
    const auto values = parameter_values(p.series);
    panel.x.scale = values.front() > 0 && values.back() / values.front() >= kLogSpan
                        ? Scale::log
                        : Scale::linear;
    const auto defaults = doc.parameter_defaults.find(p.problem);
    if (defaults != doc.parameter_defaults.end() && defaults->second.contains(key))
      panel.marks.push_back({defaults->second.at(key), "default"});
    else
      no_default = true;
    plot.panels.push_back(std::move(panel));
  }
  figure.caption_md = figure_text("sweep", TemplateData("key", key));
  TemplateData left("n", std::to_string(left_out));
  left.set("floor", fmt::format("{:g}", schema::kErrorNoiseFloorPercent));
  if (left_out > 0)
    figure.notes.push_back(figure_text("sweep_left_out", left));
  if (no_default)
    figure.notes.push_back(figure_text("sweep_no_default", TemplateData("key", key)));
  return plot;
}

std::string sweep_figure_file(const std::string& key) {
  std::string stem;
  for (char c : key)
    stem += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
  return "figures/sweep_" + stem + ".png";
}

FigureSet render_sweep_figures(const schema::ResultsDocument& doc,
                               const std::filesystem::path& out_root,
                               const FigureOptions& options) {
  FigureSet set;
  const auto keys = swept_keys(doc);
  if (keys.empty())
    return set;
  GnuplotWriter writer(options);
  set.unavailable = writer.unavailable();
  for (const auto& key : keys) {
    const auto series = sweep_series(doc, key);
    const auto panels = sweep_panels(series);
    if (panels.empty())
      continue;
    Figure figure(FigureKind::sweep, sweep_figure_file(key));
    writer.draw(sweep_plot(doc, key, panels, figure), out_root, figure);
    set.figures.push_back(std::move(figure));
  }
  return set;
}

}  // namespace cs::reports

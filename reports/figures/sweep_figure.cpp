#include "reports/figures/sweep_figure.hpp"

#include <algorithm>
#include <cmath>

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
  panel.series.insert(panel.series.end(), {line, done, failed});
  return left_out;
}

}  // namespace

std::vector<SeriesRefs> sweep_panels(const std::vector<ParameterSeries>& series) {
  std::vector<SeriesRefs> panels;
  for (const auto& s : series) {
    if (!shown_in_answers(s, series))
      continue;
    const auto same_panel = [&](const SeriesRefs& panel) {
      const ParameterSeries& o = *panel.front();  // of the same mesh: the finest swept
      return o.spec.problem == s.spec.problem && o.quantity == s.quantity &&
             o.spec.element == s.spec.element;
    };
    if (const auto it = std::ranges::find_if(panels, same_panel); it != panels.end())
      it->push_back(&s);
    else
      panels.push_back({&s});
  }
  return panels;
}

Plot sweep_plot(const schema::ResultsDocument& doc, const std::string& key,
                const std::vector<SeriesRefs>& panels, Figure& figure) {
  Plot plot{.title = fmt::format("|error| against {} (open circles: not converged)", key),
            .columns = 3,
            .panel_width = 520,
            .panel_height = 400};
  int left_out = 0;
  bool no_default = false;
  for (const SeriesRefs& series : panels) {
    const schema::CaseSpec& spec = series.front()->spec;
    PlotPanel panel{fmt::format("{} {}, mesh {}, {}", schema::label(spec.problem),
                                schema::label(series.front()->quantity),
                                schema::to_string(spec.mesh), schema::to_string(spec.element)),
                    {key},
                    {"|error| (%)", Scale::log}};
    for (const ParameterSeries* s : series)
      left_out += add_curves(panel, *s);
    const auto values = parameter_values(series);
    panel.x.scale = values.front() > 0 && values.back() / values.front() >= kLogSpan
                        ? Scale::log
                        : Scale::linear;
    const auto defaults = doc.parameter_defaults.find(spec.problem);
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
  for (const char c : key) {
    const auto byte = static_cast<unsigned char>(c);
    stem += std::isalnum(byte) != 0 || c == '_' ? std::string(1, c) : fmt::format("-{:02x}", byte);
  }
  return "figures/sweep_" + stem + ".png";
}

FigureSet render_sweep_figures(const schema::ResultsDocument& doc,
                               const std::filesystem::path& out_root,
                               const FigureOptions& options) {
  const auto keys = swept_keys(doc);
  if (keys.empty())
    return {};
  std::vector<Plot> plots;
  std::vector<Figure> figures;
  for (const auto& key : keys) {
    const auto series = sweep_series(doc, key);
    const auto panels = sweep_panels(series);
    if (panels.empty())
      continue;
    Figure figure(FigureKind::sweep, sweep_figure_file(key));
    plots.push_back(sweep_plot(doc, key, panels, figure));
    figures.push_back(std::move(figure));
  }
  return draw_figures(plots, std::move(figures), out_root, options);
}

}  // namespace cs::reports

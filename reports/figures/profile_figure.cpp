// The profile figure (figures/figures.hpp): the study's Figure 4 for any problem with profiles.

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "reports/figures/figures.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {
namespace {

/// The mesh of a curve by its dashes (C dotted, M dashed, F solid) and width.
constexpr std::array<int, 3> kMeshDash{3, 2, 1};
constexpr std::array<double, 3> kMeshWidth{1.3, 1.5, 2.0};

Points points(const std::vector<double>& x, const std::vector<double>& y) {
  Points out;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (std::isfinite(x[i]) && std::isfinite(y[i]))
      out.emplace_back(x[i], y[i]);
  }
  return out;
}

/// The C, M and F curves of one option class in its colour (titled by mesh) and the exact one.
PlotPanel class_panel(const ResultsIndex& index, const OptionClass& cls, const Slot& slot,
                      Points& exact) {
  PlotPanel panel{cls.label(),
                  {fmt::format("x / {}", schema::symbol(length_scale_of(index, slot.problem)))},
                  {"-sigma_z / p"}};
  const schema::RowVerdict* row = class_row(index, cls, slot);
  for (const auto mesh : kMeshes) {
    const schema::CaseResult* c = row ? index.case_of(*row, mesh) : nullptr;
    if (c == nullptr || c->profile.x_over_a.empty())
      continue;
    if (exact.empty())
      exact = points(c->exact_profile.x_over_a, c->exact_profile.sigma_z_over_p);
    const std::size_t m = mesh_index(mesh);
    panel.series.push_back({name_of(mesh), option_colour(cls.members.front()), Mark::line,
                            kMeshDash[m], 7, kMeshWidth[m],
                            points(c->profile.x_over_a, c->profile.sigma_z_over_p)});
  }
  return panel;
}

/// Where any curve is above 1 % of the highest peak, widened 15 %.
std::optional<std::pair<double, double>> profile_range(const std::vector<PlotPanel>& panels) {
  Points all;
  for (const auto& p : panels)
    std::ranges::copy(points_of(p), std::back_inserter(all));
  double peak = 0, lo = INFINITY, hi = -INFINITY;
  for (const auto& [x, y] : all)
    peak = std::max(peak, std::abs(y));
  for (const auto& [x, y] : all) {
    if (std::abs(y) > 0.01 * peak) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  }
  if (!(hi > lo))
    return std::nullopt;
  return std::pair(lo < 0 ? 1.15 * lo : 0.0, 1.15 * hi);
}

/// The largest spacing of any curve's points around x: a zoom narrower than it would show no
/// point of the coarse mesh.
double spacing_at(const std::vector<PlotPanel>& panels, double x) {
  double widest = 0;
  for (const auto& p : panels) {
    for (const auto& s : p.series) {
      const auto after = std::ranges::find_if(s.xy, [x](const auto& q) { return q.first >= x; });
      if (after != s.xy.begin() && after != s.xy.end())
        widest = std::max(widest, after->first - std::prev(after)->first);
    }
  }
  return widest;
}

/// The peak in a narrow band (the Steuermann edge) is too small to judge at the scale of the
/// whole profile: every class's C, M and F around the exact peak, x where the exact curve is
/// above 80 % of its peak, widened to hold points of the coarsest curve, y spanning the curves'
/// own peaks there (within 0.5 to 1.6 times the exact peak).
std::optional<PlotPanel> peak_zoom(const std::vector<PlotPanel>& panels, const Points& exact) {
  const auto peak = std::ranges::max_element(exact, {}, &std::pair<double, double>::second);
  if (peak == exact.end() || !(peak->second > 0))
    return std::nullopt;
  double x_lo = peak->first, x_hi = peak->first;
  for (const auto& [x, y] : exact) {
    if (y >= 0.8 * peak->second) {
      x_lo = std::min(x_lo, x);
      x_hi = std::max(x_hi, x);
    }
  }
  const double margin =
      std::max({0.02, 0.25 * (x_hi - x_lo), 1.5 * spacing_at(panels, peak->first)});
  x_lo = std::max(x_lo - margin, exact.front().first);
  x_hi += margin;
  PlotPanel zoom{"zoom at the exact peak: C dotted, M dashed, F solid",
                 {panels.front().x.label, Scale::linear, std::pair(x_lo, x_hi)},
                 {"-sigma_z / p"}};
  double y_lo = 0.8 * peak->second, y_hi = 1.1 * peak->second;
  for (const auto& p : panels) {
    for (const auto& s : p.series) {
      double top = -INFINITY;
      for (const auto& [x, y] : s.xy)
        top = x >= x_lo && x <= x_hi ? std::max(top, y) : top;
      if (!std::isfinite(top))
        continue;
      y_lo = std::min(y_lo, std::max(0.5 * peak->second, 0.97 * top));
      y_hi = std::max(y_hi, std::min(1.6 * peak->second, 1.03 * top));
      zoom.series.push_back(s);
      zoom.series.back().title = s.dash == 1 ? p.title : "";
    }
  }
  zoom.y.range = std::pair(y_lo, y_hi);
  zoom.series.push_back(line_series("exact", "#000000", exact, 1, 1.0));
  return zoom;
}

}  // namespace

Plot profile_plot(const ResultsIndex& index, schema::ProblemId problem, schema::Element element,
                  Figure& figure) {
  Plot plot{.title = fmt::format("{} {}: -sigma_z/p on z = 0, meshes C (dotted), M (dashed), F "
                                 "(solid)",
                                 schema::label(problem), schema::to_string(element)),
            .columns = 3,
            .panel_width = 520,
            .panel_height = 380,
            .key_columns = 4};
  const schema::ProblemRecord* p = index.problem(problem);
  if (p == nullptr || p->quantities.empty())
    return plot;
  const Slot slot{problem, p->quantities.front().quantity, element};
  Points exact;
  for (const auto& cls : coincidence_classes(index, all_options(), {slot})) {
    PlotPanel panel = class_panel(index, cls, slot, exact);
    if (!panel.series.empty())
      plot.panels.push_back(std::move(panel));
  }
  if (plot.panels.empty())
    return plot;
  if (exact.empty())
    figure.notes.push_back(figure_text("no_exact_profile"));
  const auto zoom = p->singular ? std::nullopt : peak_zoom(plot.panels, exact);
  const auto shared = profile_range(plot.panels);  // one x-range: the panels compare at a glance
  for (auto& panel : plot.panels) {
    panel.x.range = shared;
    if (!exact.empty())
      panel.series.push_back(line_series("exact", "#000000", exact, 1, 1.0));
  }
  if (zoom)
    plot.panels.push_back(*zoom);
  TemplateData caption("problem", std::string(schema::label(problem)));
  caption.set("element", name_of(element));
  caption.set("exact", !exact.empty());
  caption.set("zoom", zoom.has_value());
  caption.set("length", std::string(schema::label(length_scale_of(index, problem))));
  figure.caption_md = figure_text("profile", caption);
  return plot;
}

}  // namespace cs::reports

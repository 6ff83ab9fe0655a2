#include "reports/figures/cross_code_figure.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;
using schema::ProblemId;

/// One colour per solver (its place in the panel), the exact curve in black.
PlotPanel plot_panel(const CrossCodePanel& panel) {
  const bool punch = over_punch_width(panel.problem);
  PlotPanel out{fmt::format("{} {} {} (mesh F)", schema::label(panel.problem),
                            schema::to_string(panel.element), panel.option.label()),
                {punch ? "x / b" : "x / a", Scale::linear, std::pair(0.0, punch ? 1.6 : 1.3)},
                {"contact pressure / p"}};
  for (std::size_t i = 0; i < panel.curves.size(); ++i) {
    const bool exact = panel.curves[i].title == "exact";
    out.series.push_back({panel.curves[i].title, exact ? "#000000" : palette_colour(i),
                          exact ? Mark::line : Mark::line_points, 1, 7, exact ? 2.0 : 1.5,
                          panel.curves[i].xy});
  }
  return out;
}

}  // namespace

std::vector<Figure> render_cross_code_figure(const ResultsIndex& index, const fs::path& out_root,
                                             const FigureOptions& options) {
  const auto panels = cross_code_profile_panels(index);
  if (panels.empty())
    return {};
  Figure figure;
  figure.kind = FigureKind::profile;
  figure.file = "figures/cross_code_profiles.png";
  figure.caption_md =
      "Contact pressure on the fine mesh, one curve per solver, against the exact pressure "
      "(H<sub>p</sub>: x/a; S(1/3): x/b); the option set of each panel is in its title.";
  for (const auto& p : panels) {
    for (const auto& m : p.missing)
      figure.notes.push_back(fmt::format("{} {} {}: no pressure from {}.",
                                         schema::to_string(p.problem), schema::to_string(p.element),
                                         p.option.label(), m));
  }
  Plot plot{"Contact pressure per solver against the exact one (fine mesh)",
            {},
            2,
            560,
            400,
            KeyPlace::inside,
            1};
  for (const auto& p : panels)
    plot.panels.push_back(plot_panel(p));
  GnuplotWriter writer(options);
  writer.draw(plot, out_root, figure);
  return {figure};
}

}  // namespace cs::reports

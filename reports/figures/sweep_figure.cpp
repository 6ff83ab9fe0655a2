#include "reports/figures/sweep_figure.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <system_error>
#include <tuple>

#include <fmt/format.h>

#include "reports/figures/gnuplot.hpp"
#include "reports/figures/plain_label.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

/// |error| below this (%) is drawn at it: a log axis has no zero.
constexpr double kErrorFloorPercent = 1e-4;
/// The values span this ratio or more: a log x-axis.
constexpr double kLogSpan = 100.0;

std::string panel_title(const SweepPanel& p) {
  return fmt::format("{} {}, mesh {}, {}", plain_label(schema::label(p.problem)),
                     plain_label(schema::label(p.quantity)), schema::to_string(p.mesh),
                     schema::to_string(p.element));
}

/// The data file of one curve: value, |error|, converged (1/0); the curve drawn through all.
void write_curve(const SweepSeries& s, schema::Quantity q, const fs::path& file) {
  std::ofstream out(file);
  out.precision(12);
  for (const auto& p : s.points) {
    const auto e = SweepSeries::error(p, q);
    if (e)
      out << p.value << ' ' << std::max(std::abs(*e), kErrorFloorPercent) << ' '
          << (SweepSeries::converged(p) ? 1 : 0) << '\n';
  }
}

std::string panel_script(const SweepPanel& panel, const fs::path& work, const std::string& stem,
                         const std::string& key) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto* s : panel.series) {
    for (const auto& p : s->points) {
      lo = std::min(lo, p.value);
      hi = std::max(hi, p.value);
    }
  }
  const bool logx = lo > 0 && hi / lo >= kLogSpan;
  std::string script =
      fmt::format("set title {}\nset xlabel {}\nset ylabel '|error| (%)'\n{}set logscale y\n",
                  gnuplot_quote(panel_title(panel)), gnuplot_quote(key),
                  logx ? "set logscale x\nset format x '%.0e'\n" : "unset logscale x\n");
  std::string plots;
  for (std::size_t i = 0; i < panel.series.size(); ++i) {
    const SweepSeries& s = *panel.series[i];
    const fs::path data = work / fmt::format("{}_{}.dat", stem, i);
    write_curve(s, panel.quantity, data);
    const auto& a = schema::traits(s.base.algorithm);
    const auto& c = schema::traits(s.base.contact);
    plots += fmt::format(
        "{}{} using 1:2 with lines lw 1.5 dt {} lc rgb '{}' title {}, '' using 1:($3 > 0 ? $2 : "
        "1/0) with points pt {} lc rgb '{}' notitle, '' using 1:($3 > 0 ? 1/0 : $2) with points "
        "pt 6 ps 1.5 lc rgb '{}' notitle",
        plots.empty() ? "plot " : ", ", gnuplot_quote(data.string()), c.dash, a.colour,
        gnuplot_quote(s.option_label()), c.point, a.colour, a.colour);
  }
  return script + plots + "\n";
}

void draw(const Gnuplot& gnuplot, const fs::path& work, const fs::path& out_root,
          const std::string& key, const std::vector<SweepPanel>& panels, Figure& figure) {
  const fs::path png = out_root / figure.file;
  std::error_code ec;
  fs::create_directories(png.parent_path(), ec);
  const int n = static_cast<int>(panels.size());
  const int cols = std::min(3, n), rows = (n + cols - 1) / cols;
  std::string script = fmt::format(
      "set terminal {} size {},{} noenhanced{}\nset output {}\nset grid\nset key below\n"
      "set datafile missing '?'\nset multiplot layout {},{} title {}\n",
      gnuplot.terminal, cols * 520, rows * 420 + 40,
      gnuplot.terminal == "pngcairo" ? " font 'Sans,9'" : "", gnuplot_quote(png.string()), rows,
      cols, gnuplot_quote(fmt::format("|error| against {} (open circles: not converged)", key)));
  for (std::size_t i = 0; i < panels.size(); ++i)
    script += panel_script(panels[i], work, fmt::format("sweep_{}_{}", key, i), key);
  script += "unset multiplot\nset output\n";
  const fs::path script_file = work / fmt::format("sweep_{}.gp", key);
  std::ofstream(script_file) << script;
  figure.error = run_gnuplot(gnuplot, script_file, work / fmt::format("sweep_{}.log", key));
  figure.produced =
      figure.error.empty() && fs::is_regular_file(png, ec) && fs::file_size(png, ec) > 0;
  if (!figure.produced && figure.error.empty())
    figure.error = "gnuplot wrote no image";
}

}  // namespace

std::vector<SweepPanel> sweep_panels(const std::vector<SweepSeries>& series) {
  using Key = std::tuple<schema::ProblemId, schema::Quantity, schema::MeshLevel, schema::Element>;
  std::map<Key, std::size_t> slot;
  std::vector<SweepPanel> panels;
  for (const auto& s : series) {
    if (s.points.empty() || !on_finest_mesh(s, series))
      continue;
    for (const auto& q : s.points.front().result->quantities) {
      if (q.quantity == schema::Quantity::contact_half_width)
        continue;  // graded apart: it moves by whole nodes
      const Key key{s.base.problem, q.quantity, s.base.mesh, s.base.element};
      const auto [it, fresh] = slot.try_emplace(key, panels.size());
      if (fresh)
        panels.push_back({s.base.problem, q.quantity, s.base.mesh, s.base.element, {}});
      panels[it->second].series.push_back(&s);
    }
  }
  return panels;
}

std::string sweep_figure_file(const std::string& key) {
  std::string stem;
  for (char c : key)
    stem += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
  return "figures/sweep_" + stem + ".png";
}

FigureSet render_sweep_figures(const schema::ResultsDocument& doc, const fs::path& out_root,
                               const FigureOptions& options) {
  FigureSet set;
  const auto keys = swept_keys(doc);
  if (keys.empty())
    return set;
  const auto gnuplot = find_gnuplot(options.gnuplot_program);
  if (!gnuplot) {
    set.unavailable =
        fmt::format("{} not found or without a PNG terminal", options.gnuplot_program);
    return set;
  }
  ScratchDir work;
  for (const auto& key : keys) {
    const auto series = sweep_series(doc, key);
    const auto panels = sweep_panels(series);
    if (panels.empty())
      continue;
    Figure figure;
    figure.kind = FigureKind::convergence;
    figure.file = sweep_figure_file(key);
    figure.caption_md = fmt::format("|error| (%) against {}, one curve per option set", key);
    draw(*gnuplot, work.path(), out_root, key, panels, figure);
    set.figures.push_back(std::move(figure));
  }
  return set;
}

}  // namespace cs::reports

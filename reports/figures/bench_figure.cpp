#include "reports/figures/bench_figure.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/figures/gnuplot.hpp"
#include "reports/figures/plain_label.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

/// The relative file of the chart.
constexpr const char* kFile = "figures/bench_time.png";
/// Gap between clusters of bars, in bar widths (gnuplot's `histogram clustered gap`).
constexpr int kGap = 1;

using schema::ContactKind;

template <schema::Axis E>
std::string name(E v) {
  return std::string(schema::to_string(v));
}

/// One panel: the cases of one model, as bars of algorithms grouped by discretization.
struct BarPanel {
  BenchModel model;
  std::vector<ContactKind> contacts;  ///< those present, in the report's order
  std::vector<BenchMethod> algorithms;
  std::map<std::pair<ContactKind, BenchMethod>, const ContactBenchmark*> cases;  ///< by (c, a)
  std::optional<double> reference_ms;
};

/// Per problem and element, the cases of the finest mesh with a timed case, in the report's
/// order.
std::vector<BarPanel> bar_panels(const BenchResults& bench) {
  std::map<std::tuple<int, int>, BenchModel> finest;  // (problem, element) rank -> model
  for (const auto& b : bench.contact) {
    if (!b.time_ms)
      continue;
    const auto [problem, mesh, element] = model_order(b.model);
    const auto [it, added] = finest.try_emplace({problem, element}, b.model);
    if (!added && std::get<1>(model_order(it->second)) < mesh)
      it->second = b.model;
  }
  std::vector<BarPanel> panels;
  for (const auto& [rank, model] : finest) {
    BarPanel panel{model, {}, {}, {}, std::nullopt};
    for (const auto& b : bench.contact) {
      if (b.model == model) {
        panel.cases[{b.contact, b.algorithm}] = &b;
        panel.reference_ms = panel.reference_ms ? panel.reference_ms : b.reference_ms;
      }
    }
    for (const auto c : bench_contacts()) {
      if (std::any_of(panel.cases.begin(), panel.cases.end(),
                      [&](const auto& kv) { return kv.first.first == c; }))
        panel.contacts.push_back(c);
    }
    for (const auto a : schema::values<BenchMethod>()) {
      if (std::any_of(panel.cases.begin(), panel.cases.end(),
                      [&](const auto& kv) { return kv.first.second == a; }))
        panel.algorithms.push_back(a);
    }
    panels.push_back(std::move(panel));
  }
  return panels;
}

const ContactBenchmark* find_case(const BarPanel& panel, ContactKind contact,
                                  BenchMethod algorithm) {
  const auto it = panel.cases.find({contact, algorithm});
  return it == panel.cases.end() ? nullptr : it->second;
}

/// The data file: one line per discretization, one column of times per algorithm ('?': none).
std::string write_bars(const BarPanel& panel, const fs::path& file) {
  std::ofstream out(file);
  out.precision(10);
  for (const auto c : panel.contacts) {
    out << schema::to_string(c);
    for (const auto a : panel.algorithms) {
      const ContactBenchmark* b = find_case(panel, c, a);
      if (b != nullptr && b->time_ms)
        out << ' ' << *b->time_ms;
      else
        out << " ?";
    }
    out << '\n';
  }
  return file.string();
}

std::string plain_model(const BenchModel& m) {
  return fmt::format("{}, mesh {}, {}", plain_label(schema::label(m.problem)), name(m.mesh),
                     name(m.element));
}

/// The labels above the bars, on an opaque box so that the lines do not cross them: the ratio,
/// with '*' when the case did not converge. A bar of cluster i and column j of n stands at
/// x = i + (j - (n - 1) / 2) / (n + gap).
std::string ratio_labels(const BarPanel& panel) {
  std::string s = "unset label\n";
  const double n = static_cast<double>(panel.algorithms.size());
  for (std::size_t i = 0; i < panel.contacts.size(); ++i) {
    for (std::size_t j = 0; j < panel.algorithms.size(); ++j) {
      const ContactBenchmark* b = find_case(panel, panel.contacts[i], panel.algorithms[j]);
      if (b == nullptr || !b->time_ms || !b->ratio)
        continue;
      const double x = static_cast<double>(i) + (static_cast<double>(j) - (n - 1) / 2) / (n + kGap);
      s += fmt::format("set label {} at {},{} center offset 0,0.6 font ',8' front boxed\n",
                       gnuplot_quote(fmt::format("{:.2f}{}", *b->ratio, b->converged() ? "" : "*")),
                       x, *b->time_ms);
    }
  }
  return s;
}

std::string panel_script(const BarPanel& panel, const fs::path& work, std::size_t index,
                         double max_ratio) {
  double top = 0;
  for (const auto& [key, b] : panel.cases)
    top = std::max(top, b->time_ms.value_or(0));
  if (panel.reference_ms)
    top = std::max(top, max_ratio * *panel.reference_ms);
  std::string s = fmt::format(
      "set title {}\nset ylabel 'time (ms)'\nset xrange [-0.5:{}]\nset yrange [0:{}]\n",
      gnuplot_quote(plain_model(panel.model) +
                    (panel.reference_ms ? fmt::format(": reference {} ms",
                                                      format_milliseconds(*panel.reference_ms))
                                        : std::string())),
      static_cast<double>(panel.contacts.size()) - 0.5, top > 0 ? top * 1.15 : 1.0);
  s += ratio_labels(panel);
  const std::string data = write_bars(panel, work / fmt::format("bench_{}.dat", index));
  std::string plots;
  for (std::size_t j = 0; j < panel.algorithms.size(); ++j) {
    plots += fmt::format("{}{} using {}{} title {} lc rgb '{}'", plots.empty() ? "plot " : ", ",
                         j == 0 ? gnuplot_quote(data) : std::string("''"), j + 2,
                         j == 0 ? ":xtic(1)" : "", gnuplot_quote(name(panel.algorithms[j])),
                         schema::traits(study_algorithm(panel.algorithms[j])).colour);
  }
  if (panel.reference_ms) {
    plots += fmt::format(", {} with lines dt 2 lw 1.5 lc rgb 'black' title 'reference (ratio 1)'",
                         *panel.reference_ms);
    plots += fmt::format(", {} with lines dt 4 lw 1.5 lc rgb '#d62728' title {}",
                         max_ratio * *panel.reference_ms,
                         gnuplot_quote(fmt::format("ratio {:g} (target)", max_ratio)));
  }
  return s + plots + "\n";
}

void draw(const Gnuplot& gnuplot, const fs::path& work, const fs::path& out_root, Figure& figure,
          const std::vector<BarPanel>& panels, double max_ratio) {
  const fs::path png = out_root / figure.file;
  std::error_code ec;
  fs::create_directories(png.parent_path(), ec);
  const int n = static_cast<int>(panels.size());
  const int cols = std::min(2, n), rows = (n + cols - 1) / cols;
  std::string script = fmt::format(
      "set terminal {} size {},{} noenhanced{}\nset output {}\n"
      "set style data histograms\nset style histogram clustered gap {}\n"
      "set style fill solid 0.85 border -1\nset datafile missing '?'\nset grid ytics\n"
      "set style textbox opaque noborder margins 0.5, 0.5\n"
      "set key below horizontal\nset format y '%g'\n"
      "set multiplot layout {},{} title 'Time of the contact analysis per algorithm (ratio to "
      "the reference above each bar)'\n",
      gnuplot.terminal, cols * 620, rows * 440 + 40,
      gnuplot.terminal == "pngcairo" ? " font 'Sans,10'" : "", gnuplot_quote(png.string()), kGap,
      rows, cols);
  for (std::size_t i = 0; i < panels.size(); ++i)
    script += panel_script(panels[i], work, i, max_ratio);
  script += "unset multiplot\nset output\n";
  const fs::path script_file = work / "bench_time.gp";
  std::ofstream(script_file) << script;
  figure.error = run_gnuplot(gnuplot, script_file, work / "bench_time.log");
  figure.produced =
      figure.error.empty() && fs::is_regular_file(png, ec) && fs::file_size(png, ec) > 0;
  if (!figure.produced && figure.error.empty())
    figure.error = "gnuplot wrote no image";
}

std::string caption(const std::vector<BarPanel>& panels, const BenchTarget& target) {
  std::vector<std::string> models;
  bool any_failed = false;
  for (const auto& p : panels) {
    models.push_back(model_md(p.model));
    for (const auto& [key, b] : p.cases)
      any_failed = any_failed || !b->converged();
  }
  std::string out = fmt::format(
      "Time of the contact analysis (ms) per algorithm, grouped by contact discretization, for "
      "each problem and element at the finest mesh measured ({}); above each bar its ratio to "
      "the reference. Dashed black: the reference (one assembly + factorization + solve, ratio "
      "1); dash-dotted red: ratio {:g}, the target.",
      fmt::format("{}", fmt::join(models, "; ")), target.max_ratio);
  if (any_failed)
    out += " A ratio marked * is of a case that did not converge; a missing bar, of an error.";
  return out;
}

}  // namespace

FigureSet render_bench_figures(const BenchResults& bench, const fs::path& out_root,
                               const BenchTarget& target, const FigureOptions& options) {
  FigureSet set;
  const std::vector<BarPanel> panels = bar_panels(bench);
  if (panels.empty())
    return set;
  Figure figure{FigureKind::bench,       std::nullopt, std::nullopt, kFile,
                caption(panels, target), {},           false,        {}};
  const auto gnuplot = find_gnuplot(options.gnuplot_program);
  if (!gnuplot) {
    set.unavailable = fmt::format(
        "`{}` with a PNG terminal was not found, so the chart was not "
        "drawn",
        options.gnuplot_program);
    figure.error = set.unavailable;
  } else {
    const ScratchDir work;
    draw(*gnuplot, work.path(), out_root, figure, panels, target.max_ratio);
  }
  set.figures.push_back(std::move(figure));
  return set;
}

}  // namespace cs::reports

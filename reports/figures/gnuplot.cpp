#include "reports/figures/gnuplot.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <system_error>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "platform/available_cores.hpp"
#include "platform/child_process.hpp"
#include "reports/report_error.hpp"

namespace cs::reports {

namespace fs = std::filesystem;

namespace {

/// Estimated width of a character of the 10-point key font, and of a key entry's line sample,
/// in pixels: enough to keep every key column inside its panel.
constexpr int kCharPixels = 7, kSamplePixels = 80, kKeyRowPixels = 18;

/// gnuplot runs as a child with an argument vector, never through a shell; SIGINT/SIGTERM to us
/// reach it too (platform/interrupts.hpp).
platform::ChildResult run(std::vector<std::string> argv, const fs::path& log) {
  platform::ChildOptions options;
  options.argv = std::move(argv);
  options.stdout_path = log;
  options.stderr_path = log;
  options.time_limit_seconds = 120;
  return platform::run_child(options);
}

bool has_control_character(const std::string& text) {
  return std::ranges::any_of(text, [](unsigned char c) { return c < 0x20 || c == 0x7f; });
}

/// `text` as a gnuplot single-quoted string ('' for a quote); a control character would end
/// the command and start another, so such text is refused.
std::string quote(const std::string& text) {
  if (has_control_character(text))
    throw ReportError("figure: a path or label holds a control character; not written to a script");
  std::string out = "'";
  for (char c : text)
    out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string text(const std::string& markdown) {
  return quote(plain_label(markdown));
}

/// "gnuplot exited with status 1: line 3: ..." from the log of a failed run.
std::string failure(const platform::ChildResult& result, const fs::path& log) {
  if (result.exit_code < 0)
    return "gnuplot " + result.describe();
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("line ") != std::string::npos || line.find("rror") != std::string::npos)
      return fmt::format("gnuplot exited with status {}: {}", result.exit_code, line);
  }
  return fmt::format("gnuplot exited with status {}", result.exit_code);
}

std::pair<double, double> data_range(const PlotPanel& panel, bool x) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& [px, py] : points_of(panel)) {
    const double v = x ? px : py;
    if (std::isfinite(v) && (v > 0 || (x ? panel.x : panel.y).scale == Scale::linear)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  return {lo, hi};
}

/// 1-2-5 tics on a log axis spanning less than two decades (else gnuplot shows one or none).
std::string short_log_tics(double lo, double hi) {
  if (!(lo > 0) || !(hi / lo < 100))
    return "autofreq";
  std::string tics;
  for (int k = static_cast<int>(std::floor(std::log10(lo))) - 1;
       k <= static_cast<int>(std::ceil(std::log10(hi))); ++k) {
    for (const double m : {1.0, 2.0, 5.0})
      tics += fmt::format("{}{:g}", tics.empty() ? "(" : ", ", m * std::pow(10.0, k));
  }
  return tics + ")";
}

std::string axis_script(const PlotPanel& panel, bool x) {
  const PlotAxis& a = x ? panel.x : panel.y;
  const char* n = x ? "x" : "y";
  const bool log = a.scale == Scale::log;
  auto [lo, hi] = data_range(panel, x);
  std::string s = fmt::format("set {0}label {1}\n{2}set logscale {0}\nset format {0} '%g'\n", n,
                              text(a.label), log ? "" : "un");
  std::string tics;
  for (const auto& [v, label] : a.tics)
    tics += fmt::format("{}{} {:.10g}", tics.empty() ? "(" : ", ", text(label), v);
  s += fmt::format("set {}tics {}\n", n,
                   tics.empty() ? (log ? short_log_tics(lo, hi) : "autofreq") : tics + ")");
  if (a.range)
    std::tie(lo, hi) = *a.range;
  else if (log && lo > 0 && hi >= lo)
    std::tie(lo, hi) = std::pair(lo / 1.5, hi * 1.5);
  else
    return s + fmt::format("set {}range [*:*]{}\n", n, a.reversed ? " reverse" : "");
  if (a.reversed)
    std::swap(lo, hi);
  return s + fmt::format("set {}range [{:.10g}:{:.10g}]\n", n, lo, hi);
}

std::string style(const PlotSeries& s) {
  const std::string colour = fmt::format("lc rgb {}", quote(s.colour));
  switch (s.mark) {
    case Mark::line:
      return fmt::format("lines lw {} dt {} {}", s.width, s.dash, colour);
    case Mark::line_points:
      return fmt::format("linespoints lw {} dt {} pt {} ps 0.9 {}", s.width, s.dash, s.point,
                         colour);
    case Mark::points:
      return fmt::format("points pt {} ps 0.9 {}", s.point, colour);
    case Mark::open_points:
      return fmt::format("points pt 6 ps 1.5 {}", colour);
    case Mark::bars:
      return fmt::format("boxes fs solid 0.85 border -1 {}", colour);
  }
  return "lines";
}

/// The data file of a series: "x y" lines, a blank line for a NaN point (a break).
std::string write_data(const fs::path& file, const PlotSeries& s) {
  std::ofstream out(file);
  for (const auto& [x, y] : s.xy)
    out << (std::isnan(x) || std::isnan(y) ? std::string("\n")
                                           : fmt::format("{:.10g} {:.10g}\n", x, y));
  return file.string();
}

std::string panel_script(const PlotPanel& panel, const fs::path& stem) {
  std::string s = fmt::format("unset label\nunset arrow\nset title {}\nset size {}\n",
                              text(panel.title), panel.equal_aspect ? "ratio -1" : "noratio");
  if (points_of(panel).empty()) {
    // gnuplot cannot autoscale a plot without points: fixed ranges and a word of explanation.
    s += "set xrange [0.1:1]\nset yrange [0.1:1]\nset xtics autofreq\nset ytics autofreq\n"
         "set label 'nothing to draw' at graph 0.5, 0.5 center\n";
  } else {
    s += axis_script(panel, true) + axis_script(panel, false);
  }
  if (panel.bar_width > 0)
    s += fmt::format("set boxwidth {:.10g} absolute\n", panel.bar_width);
  for (const auto& m : panel.marks) {
    s += fmt::format(
        "set arrow from {0:.10g}, graph 0 to {0:.10g}, graph 1 nohead dt 2 lw 1.5 lc rgb "
        "'#444444' front\nset label {1} at {0:.10g}, graph 0.95 left offset 0.4,0 front\n",
        m.x, text(m.label));
  }
  for (const auto& l : panel.labels)
    s += fmt::format("set label {} at {:.10g},{:.10g} center offset 0,0.6 font ',8' front boxed\n",
                     text(l.text), l.x, l.y);
  std::string plots;
  for (std::size_t i = 0; i < panel.series.size(); ++i) {
    const PlotSeries& series = panel.series[i];
    // A series with nothing to draw keeps its key entry (e.g. "error 0 on every mesh").
    const std::string source =
        series.xy.empty()
            ? std::string("NaN")
            : quote(write_data(fmt::format("{}_{}.dat", stem.string(), i), series)) + " using 1:2";
    plots += fmt::format("{}{} with {} {}", plots.empty() ? "plot " : ", \\\n     ", source,
                         style(series),
                         series.title.empty() ? "notitle" : "title " + text(series.title));
  }
  return s + (plots.empty() ? "plot NaN notitle" : plots) + "\n";
}

}  // namespace

std::string plain_label(std::string_view markdown) {
  constexpr std::string_view kPrime = "′";
  std::string out;
  for (std::size_t i = 0; i < markdown.size();) {
    if (markdown.substr(i, kPrime.size()) == kPrime) {
      out += '\'';
      i += kPrime.size();
    } else if (markdown[i] != '<' || markdown.find('>', i) == std::string_view::npos) {
      out += markdown[i++];
    } else {
      const std::size_t close = markdown.find('>', i);
      const std::string_view tag = markdown.substr(i + 1, close - i - 1);
      out += tag == "sub" ? "_" : tag == "sup" ? "^" : "";
      i = close + 1;
    }
  }
  return out;
}

std::optional<Gnuplot> find_gnuplot(const std::string& program) {
  for (const char* terminal : {"pngcairo", "png"}) {
    if (run({program, "-e", std::string("set terminal ") + terminal}, {}).succeeded())
      return Gnuplot{program, terminal};
  }
  return std::nullopt;
}

GnuplotWriter::GnuplotWriter(const FigureOptions& options)
    : gnuplot_(find_gnuplot(options.gnuplot_program)) {
  // Scripts name files in the scratch directory: a TMPDIR with a control character is not used.
  const std::string base = fs::temp_directory_path().string();
  std::string pattern = (has_control_character(base) ? "/tmp" : base) + "/cs-report-XXXXXX";
  if (gnuplot_ && mkdtemp(pattern.data()) != nullptr)
    work_ = pattern;
  else if (gnuplot_)
    unavailable_ = "no temporary directory could be created, so no figure was drawn";
  else
    unavailable_ = fmt::format("`{}` with a PNG terminal was not found, so no figure was drawn",
                               options.gnuplot_program);
  if (work_.empty())
    gnuplot_.reset();
}

GnuplotWriter::~GnuplotWriter() {
  std::error_code ec;
  if (!work_.empty())
    fs::remove_all(work_, ec);
}

void GnuplotWriter::draw(const Plot& plot, const fs::path& out_root, Figure& figure) const {
  figure.produced = false;
  figure.error = !gnuplot_ ? unavailable_ : plot.panels.empty() ? "nothing to plot" : "";
  if (!figure.error.empty())
    return;
  try {
    figure.error = run_script(plot, out_root / figure.file);
  } catch (const std::exception& e) {  // e.g. a label with a control character
    figure.error = e.what();
  }
  std::error_code ec;
  figure.produced = figure.error.empty() && fs::file_size(out_root / figure.file, ec) > 0 && !ec;
  if (!figure.produced && figure.error.empty())
    figure.error = "gnuplot wrote no image";
}

void GnuplotWriter::draw_all(const std::vector<Plot>& plots, const fs::path& out_root,
                             std::vector<Figure>& figures) const {
  std::atomic<std::size_t> next{0};
  const auto drawer = [&] {
    for (std::size_t i = next++; i < plots.size(); i = next++)
      draw(plots[i], out_root, figures[i]);
  };
  const std::size_t threads =
      std::min(plots.size(), static_cast<std::size_t>(platform::available_cores()));
  std::vector<std::thread> helpers;
  try {
    for (std::size_t t = 1; t < threads; ++t)
      helpers.emplace_back(drawer);
  } catch (const std::system_error&) {  // fewer threads: the others draw the rest
  }
  drawer();
  for (std::thread& helper : helpers)
    helper.join();
}

FigureSet draw_figures(const std::vector<Plot>& plots, std::vector<Figure> figures,
                       const fs::path& out_root, const FigureOptions& options) {
  const GnuplotWriter writer(options);
  FigureSet set{std::move(figures), writer.unavailable()};
  writer.draw_all(plots, out_root, set.figures);
  return set;
}

std::string GnuplotWriter::run_script(const Plot& plot, const fs::path& png) const {
  const int n = static_cast<int>(plot.panels.size());
  const int cols = std::clamp(plot.columns, 1, n), rows = (n + cols - 1) / cols;
  // The key goes below each panel in as many columns as fit its widest entry; the panel grows.
  std::size_t widest = 0, entries = 0;
  for (const auto& p : plot.panels) {
    std::size_t titled = 0;
    for (const auto& s : p.series) {
      widest = std::max(widest, plain_label(s.title).size());
      titled += !s.title.empty();
    }
    entries = std::max(entries, titled);
  }
  const int entry_px = kCharPixels * static_cast<int>(widest) + kSamplePixels;
  const int panel_w = std::max(plot.panel_width, entry_px + 40);
  const int key_cols = std::clamp(panel_w / entry_px, 1, std::max(1, plot.key_columns));
  const int key_rows = static_cast<int>((entries + key_cols - 1) / key_cols);
  const bool below = plot.key == KeyPlace::below;
  const int panel_h = plot.panel_height + (below ? kKeyRowPixels * (key_rows + 1) : 0);
  const fs::path stem = work_ / png.stem();
  std::error_code ec;
  fs::create_directories(png.parent_path(), ec);
  std::string script = fmt::format(
      "set terminal {} size {},{} noenhanced{}\nset output {}\nset grid\nset clip two\n"
      "set style textbox opaque noborder margins 0.5, 0.5\nset key {}\n"
      "set multiplot layout {},{} title {}\n",
      gnuplot_->terminal, cols * panel_w, rows * panel_h + 40,
      gnuplot_->terminal == "pngcairo" ? " font 'Sans,10'" : "", quote(png.string()),
      below ? fmt::format("below left vertical Left reverse height 1 maxcols {} maxrows {}",
                          key_cols, std::max(1, key_rows))
            : "top right Left reverse",
      rows, cols, text(plot.title));
  for (int i = 0; i < n; ++i)
    script += panel_script(plot.panels[i], fmt::format("{}_p{}", stem.string(), i));
  script += "unset multiplot\nset output\n";
  std::ofstream(stem.string() + ".gp") << script;
  const fs::path log = stem.string() + ".log";
  const platform::ChildResult result = run({gnuplot_->program, stem.string() + ".gp"}, log);
  return result.succeeded() ? std::string() : failure(result, log);
}

std::string palette_colour(std::size_t i) {
  static constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                             "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f",
                                             "#393b79", "#ad494a", "#637939", "#e7ba52", "#5254a3"};
  return kPalette[i % std::size(kPalette)];
}

}  // namespace cs::reports

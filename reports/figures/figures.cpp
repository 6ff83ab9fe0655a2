#include "reports/figures/figures.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "reports/figures/gnuplot.hpp"
#include "reports/figures/plain_label.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

using schema::ProblemId;

/// A panel of the study's Figure 4 and its caption ("{}": the problem's label).
struct StudyFigure4 {
  ProblemId problem;
  const char* caption;
};
constexpr StudyFigure4 kFigure4[] = {
    {ProblemId::H_p, "a (Hertzian contact of a cylinder, {})"},
    {ProblemId::S_1_3, "b (Steuermann contact, r<sub>e</sub>/b = 1/3)"},
};

/// What the problem's x and h are normalized by, as its record gives it (the contact
/// half-width a for a record that names none).
schema::LengthScale length_scale(const schema::ProblemRecord* p) {
  return p != nullptr && p->length_scale ? *p->length_scale
                                         : schema::LengthScale::contact_half_width_a;
}

/// "x / a", "h / b": `what` over the problem's length scale.
std::string over_length(const schema::ProblemRecord* p, std::string_view what) {
  return fmt::format("{} / {}", what, schema::symbol(length_scale(p)));
}

struct Series {
  std::string title;
  std::string color;  ///< "#rrggbb"
  int dash = 1;       ///< gnuplot dashtype
  int point = 7;      ///< gnuplot pointtype; 0 for lines only
  double width = 1.5;
  std::vector<std::pair<double, double>> xy;
};

struct Panel {
  std::string title, xlabel, ylabel;
  bool loglog = false;
  std::optional<std::pair<double, double>> xrange;
  std::vector<Series> series;
  std::optional<std::pair<double, double>> yrange{};  ///< none: autoscaled
};

std::string file_stem(const std::string& text) {
  std::string out;
  for (char c : text)
    out += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
  return out;
}

/// The plotted x-range of a log-log panel: the sizes present, widened by a factor 1.6.
std::optional<std::pair<double, double>> log_range(const std::vector<Series>& series) {
  double lo = INFINITY, hi = 0;
  for (const auto& s : series) {
    for (const auto& [x, y] : s.xy) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  }
  if (!(hi > 0) || !(lo > 0))
    return std::nullopt;
  return std::pair(lo / 1.6, hi * 1.6);
}

/// The plotted x-range of a profile: where any curve is above 1 % of its peak, widened 15 %.
std::optional<std::pair<double, double>> profile_range(const std::vector<Series>& series) {
  double peak = 0;
  for (const auto& s : series) {
    for (const auto& [x, y] : s.xy)
      peak = std::max(peak, std::abs(y));
  }
  if (peak <= 0)
    return std::nullopt;
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& s : series) {
    for (const auto& [x, y] : s.xy) {
      if (std::abs(y) > 0.01 * peak) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    }
  }
  if (!(hi > lo))
    return std::nullopt;
  return std::pair(lo < 0 ? 1.15 * lo : 0.0, hi * 1.15);
}

std::string write_data(const fs::path& dir, const std::string& name, const Series& s) {
  const fs::path file = dir / name;
  std::ofstream out(file);
  out.precision(10);
  for (const auto& [x, y] : s.xy)
    out << x << ' ' << y << '\n';
  return file.string();
}

std::string panel_script(const Panel& panel, const fs::path& dir, const std::string& stem) {
  std::string s;
  s += fmt::format("set title {}\n", gnuplot_quote(panel.title));
  s += fmt::format("set xlabel {}\nset ylabel {}\n", gnuplot_quote(panel.xlabel),
                   gnuplot_quote(panel.ylabel));
  s += panel.loglog ? "set logscale xy\nset format x '%g'\nset format y '%g'\n"
                    : "unset logscale\nset format x '%g'\nset format y '%g'\n";
  if (panel.loglog) {
    // Ticks at the element sizes of the meshes: a log axis over less than a decade has few.
    std::vector<double> sizes;
    for (const auto& series : panel.series) {
      for (const auto& [x, y] : series.xy)
        sizes.push_back(x);
    }
    std::sort(sizes.begin(), sizes.end());
    std::string tics;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      if (i > 0 && sizes[i] <= sizes[i - 1] * (1 + 1e-6))
        continue;
      tics += fmt::format("{}{:g}", tics.empty() ? "" : ", ", sizes[i]);
    }
    s += tics.empty() ? "set xtics autofreq\n" : fmt::format("set xtics ({})\n", tics);
  } else {
    s += "set xtics autofreq\n";
  }
  if (panel.xrange) {
    s += fmt::format("set xrange [{}:{}]\n", panel.xrange->first, panel.xrange->second);
  } else {
    s += "set autoscale x\n";
  }
  // Linear panels: autoscaled both ways so that a tensile (negative) value shows; 0 is kept in
  // range unless the panel sets its own (a zoom). Log panels are narrowed below.
  if (panel.yrange) {
    s += fmt::format("set yrange [{}:{}]\n", panel.yrange->first, panel.yrange->second);
  } else {
    s += panel.loglog ? "set autoscale y\n" : "set autoscale y\nset autoscale yfixmin\n";
  }
  if (panel.loglog) {
    // 1-2-5 ticks on y: a log axis over less than a decade would show one label or none.
    double lo = INFINITY, hi = 0;
    for (const auto& series : panel.series) {
      for (const auto& [x, y] : series.xy) {
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
    }
    std::string tics;
    if (hi > 0 && lo > 0 && hi / lo < 100) {
      for (int k = static_cast<int>(std::floor(std::log10(lo))) - 1;
           k <= static_cast<int>(std::ceil(std::log10(hi))); ++k) {
        for (double m : {1.0, 2.0, 5.0})
          tics += fmt::format("{}{:g}", tics.empty() ? "" : ", ", m * std::pow(10.0, k));
      }
    }
    s += tics.empty() ? "set ytics autofreq\n" : fmt::format("set ytics ({})\n", tics);
    if (hi > 0 && lo > 0)
      s += fmt::format("set yrange [{}:{}]\n", lo / 1.5, hi * 1.5);
  } else {
    s += "set ytics autofreq\n";
  }
  const bool any_points = std::any_of(panel.series.begin(), panel.series.end(),
                                      [](const Series& series) { return !series.xy.empty(); });
  s += "unset label\n";
  if (!any_points) {
    // gnuplot cannot autoscale a plot without points: fixed ranges and a word of explanation.
    s += "set xrange [0.1:1]\nset yrange [0.1:1]\nset xtics autofreq\nset ytics autofreq\n"
         "set label 'nothing to draw: every value is 0 (exact)' at graph 0.5, 0.5 center\n";
  }
  std::string plots;
  for (std::size_t i = 0; i < panel.series.size(); ++i) {
    const Series& series = panel.series[i];
    // A series with nothing to draw keeps its legend entry (e.g. "error 0 on every mesh").
    const std::string source =
        series.xy.empty()
            ? std::string("NaN")
            : gnuplot_quote(write_data(dir, fmt::format("{}_{}.dat", stem, i), series)) +
                  " using 1:2";
    plots += plots.empty() ? "plot " : ", \\\n     ";
    plots +=
        fmt::format("{} with {} lc rgb '{}' lw {} dt {}{} title {}", source,
                    series.point > 0 ? "linespoints" : "lines", series.color, series.width,
                    series.dash, series.point > 0 ? fmt::format(" pt {} ps 0.9", series.point) : "",
                    gnuplot_quote(series.title));
  }
  if (plots.empty())
    plots = "plot NaN notitle";
  return s + plots + "\n";
}

/// Writes the script of a multi-panel figure, runs gnuplot, and records the outcome.
void draw(const Gnuplot& gnuplot, const fs::path& work, const fs::path& out_root, Figure& figure,
          const std::string& title, const std::vector<Panel>& panels, int columns, int panel_w,
          int panel_h) {
  const int n = static_cast<int>(panels.size());
  const int cols = std::max(1, std::min(columns, n));
  const int rows = (n + cols - 1) / cols;
  const fs::path png = out_root / figure.file;
  std::error_code ec;
  fs::create_directories(png.parent_path(), ec);
  const std::string stem = file_stem(fs::path(figure.file).stem().string());
  // The legend of a convergence panel goes below it in two columns; the panel grows with it.
  std::size_t most_series = 0;
  for (const auto& p : panels)
    most_series = std::max(most_series, p.series.size());
  const int key_rows = static_cast<int>((most_series + 1) / 2);
  const bool profile = figure.kind == FigureKind::profile;
  const std::string key =
      profile ? "below center horizontal height 0.5"
              : fmt::format("below left vertical maxrows {} height 1.5", std::max(1, key_rows));
  if (!profile)
    panel_h += 18 * key_rows;
  std::string script = fmt::format(
      "set terminal {} size {},{} noenhanced{}\nset output {}\nset grid\nset key {}\n"
      "set multiplot layout {},{} title {}\n",
      gnuplot.terminal, cols * panel_w, rows * panel_h + 40,
      gnuplot.terminal == "pngcairo" ? " font 'Sans,10'" : "", gnuplot_quote(png.string()), key,
      rows, cols, gnuplot_quote(title));
  for (std::size_t i = 0; i < panels.size(); ++i)
    script += panel_script(panels[i], work, fmt::format("{}_p{}", stem, i));
  script += "unset multiplot\nset output\n";
  const fs::path script_file = work / (stem + ".gp");
  std::ofstream(script_file) << script;
  figure.error = run_gnuplot(gnuplot, script_file, work / (stem + ".log"));
  figure.produced =
      figure.error.empty() && fs::is_regular_file(png, ec) && fs::file_size(png, ec) > 0;
  if (!figure.produced && figure.error.empty())
    figure.error = "gnuplot wrote no image";
}

/// The points of one row: (h, |error|) or, for singular rows, (h, value). Errors below
/// schema::kErrorNoiseFloorPercent are round-off, not discretization error: they are left out
/// (no order is fitted to them) and `round_off` says so.
struct RowPoints {
  std::vector<SizePoint> points;
  bool relative_h = false;
  bool round_off = false;
};

RowPoints row_points(const ResultsIndex& index, const schema::RowVerdict& row, bool singular) {
  RowPoints out;
  std::array<std::optional<double>, 3> h;
  for (const auto mesh : kMeshes) {
    if (const schema::CaseResult* c = index.case_of(row, mesh))
      h[mesh_index(mesh)] = finite(c->element_size_h);
  }
  for (std::size_t m = 0; m < kMeshes.size(); ++m) {
    const auto& y = singular ? row.values[m] : row.errors[m];
    if (!y)
      continue;
    if (!h[m] || *h[m] <= 0)
      out.relative_h = true;
  }
  for (std::size_t m = 0; m < kMeshes.size(); ++m) {
    const auto& y = singular ? row.values[m] : row.errors[m];
    if (!y)
      continue;
    if (!singular && std::abs(*y) < schema::kErrorNoiseFloorPercent) {
      out.round_off = true;
      continue;
    }
    const double size = out.relative_h ? std::ldexp(1.0, -static_cast<int>(m)) : *h[m];
    out.points.push_back({size, std::abs(*y)});
  }
  return out;
}

/// "order 1.02", "slope -0.48" (ASCII for gnuplot; `markdown` writes the minus sign as −);
/// "at round-off" when the errors are below the noise floor and too few remain to fit.
std::string order_text(const std::optional<double>& order, bool singular, bool round_off,
                       bool markdown = false) {
  if (!order && round_off)
    return "at round-off";
  if (!order)
    return singular ? "slope n/a" : "order n/a";
  std::string number = fmt::format("{:.2f}", std::abs(*order) < 0.005 ? 0.0 : *order);
  if (markdown && number[0] == '-')
    number = "−" + number.substr(1);
  return fmt::format("{} {}", singular ? "slope" : "order", number);
}

/// Grey reference lines through the panel's data at its coarsest size: slopes 1 and 2 for an
/// error, slope -1/2 (a square-root singularity's growth) for a singular value.
void add_reference_slopes(Panel& panel, bool singular) {
  double x_lo = INFINITY, x_hi = 0.0;
  std::vector<double> at_coarsest;
  for (const auto& s : panel.series) {
    for (const auto& [x, y] : s.xy) {
      x_lo = std::min(x_lo, x);
      x_hi = std::max(x_hi, x);
    }
  }
  if (!(x_hi > x_lo) || !(x_lo > 0))
    return;
  for (const auto& s : panel.series) {
    for (const auto& [x, y] : s.xy) {
      if (x >= x_hi * (1 - 1e-9))
        at_coarsest.push_back(y);
    }
  }
  std::sort(at_coarsest.begin(), at_coarsest.end());
  const double y0 = at_coarsest[at_coarsest.size() / 2];  // the median curve's start
  const std::vector<double> slopes = singular ? std::vector<double>{-0.5} : std::vector{1.0, 2.0};
  for (const double slope : slopes) {
    Series ref{fmt::format("reference slope {:g}", slope), "#999999", 3, 0, 1.0, {}};
    for (const double x : {x_hi, x_lo})
      ref.xy.emplace_back(x, y0 * std::pow(x / x_hi, slope));
    panel.series.push_back(std::move(ref));
  }
}

/// One panel of a convergence figure: a curve per option class of one element.
Panel convergence_panel(const ResultsIndex& index, const schema::ProblemRecord& p,
                        const schema::QuantityDefinition& q, schema::Element element,
                        std::vector<ObservedOrderEntry>& orders, bool& relative, bool& zero_error) {
  const Slot slot{p.id, q.quantity, element};
  Panel panel{
      std::string(schema::to_string(element)),
      over_length(&p, "element size h"),
      p.singular ? q.definition_plain + " (grows without bound if diverging)" : "|error| (%)",
      true,
      std::nullopt,
      {}};
  for (const auto& cls : coincidence_classes(index, all_options(), {slot})) {
    const schema::RowVerdict* row = class_row(index, cls, slot);
    const RowPoints pts = row_points(index, *row, p.singular);
    const auto order = observed_order(pts.points);
    orders.push_back(
        {p.id, q.quantity, element, cls.label(), order, p.singular, pts.relative_h, pts.round_off});
    relative = relative || pts.relative_h;
    const Option& first = cls.members.front();
    Series s{fmt::format("{}: {}", cls.label(), order_text(order, p.singular, pts.round_off)),
             std::string(schema::traits(first.algorithm).colour),
             schema::traits(first.contact).dash,
             schema::traits(first.contact).point,
             1.5,
             {}};
    for (const auto& pt : pts.points) {
      if (pt.y > 0)
        s.xy.emplace_back(pt.h, pt.y);
      else
        zero_error = true;
    }
    if (s.xy.empty())
      s.title += " (error 0 on every mesh: not drawn)";
    panel.series.push_back(std::move(s));
  }
  add_reference_slopes(panel, p.singular);
  panel.xrange = log_range(panel.series);
  return panel;
}

Figure convergence_figure(const ResultsIndex& index, const Gnuplot* gnuplot, const fs::path& work,
                          const fs::path& out_root, const schema::ProblemRecord& p,
                          const schema::QuantityDefinition& q,
                          std::vector<ObservedOrderEntry>& orders) {
  const std::string id(schema::to_string(p.id)), quantity(schema::to_string(q.quantity));
  Figure fig{FigureKind::convergence,
             p.id,
             q.quantity,
             fmt::format("figures/convergence_{}_{}.png", id, quantity),
             {},
             {},
             false,
             {}};
  std::vector<Panel> panels;
  bool relative = false, zero_error = false;
  for (const auto element : schema::values<schema::Element>()) {
    if (!index.has(p.id, q.quantity, element))
      continue;
    panels.push_back(convergence_panel(index, p, q, element, orders, relative, zero_error));
  }
  fig.caption_md = fmt::format(
      "{} — {}: {} against element size, log–log, per option set (colour: algorithm; dashes and "
      "symbols: contact type); legend: the observed {} (least-squares slope over C, M, F).",
      schema::label(p.id), schema::label(q.quantity),
      p.singular ? "the edge stress" : "|error| (%)",
      p.singular ? "slope (negative: the stress grows as h → 0)" : "order of convergence");
  if (relative)
    fig.notes.push_back(
        "element_size_h missing in some cases: h taken as 1, 1/2, 1/4 of the coarse mesh.");
  if (zero_error)
    fig.notes.push_back("some errors are exactly 0 and cannot be drawn on a log scale.");
  if (gnuplot != nullptr && !panels.empty()) {
    draw(*gnuplot, work, out_root, fig,
         fmt::format("{} ({}): {} vs element size", plain_label(schema::label(p.id)),
                     q.definition_plain, p.singular ? "edge stress" : "|error|"),
         panels, 2, 760, 520);
  }
  return fig;
}

/// One panel of a profile figure: the C, M and F curves of one option class and the exact
/// curve; its series are empty when no case of the class has a profile.
Panel profile_panel(const ResultsIndex& index, const OptionClass& cls, const Slot& slot,
                    bool& has_exact) {
  static constexpr std::array<const char*, 3> kMeshColours{"#9ecae1", "#4292c6", "#08306b"};
  const schema::RowVerdict* row = class_row(index, cls, slot);
  Panel panel{cls.label(),    over_length(index.problem(slot.problem), "x"),
              "-sigma_z / p", false,
              std::nullopt,   {}};
  const schema::ExactProfile* exact = nullptr;
  for (const auto mesh : kMeshes) {
    const schema::CaseResult* c = index.case_of(*row, mesh);
    if (c == nullptr)
      continue;
    if (exact == nullptr && !c->exact_profile.empty())
      exact = &c->exact_profile;
    Series s{std::string(schema::to_string(mesh)),
             kMeshColours[mesh_index(mesh)],
             1,
             0,
             mesh == kFinestMesh ? 2.0 : 1.5,
             {}};
    for (std::size_t i = 0; i < c->profile.x_over_a.size() && i < c->profile.sigma_z_over_p.size();
         ++i) {
      const double x = c->profile.x_over_a[i], y = c->profile.sigma_z_over_p[i];
      if (std::isfinite(x) && std::isfinite(y))
        s.xy.emplace_back(x, y);
    }
    if (!s.xy.empty())
      panel.series.push_back(std::move(s));
  }
  has_exact = exact != nullptr;
  if (panel.series.empty() || exact == nullptr)
    return panel;
  Series s{"exact", "#000000", 2, 0, 2.0, {}};
  for (std::size_t i = 0; i < exact->x_over_a.size() && i < exact->sigma_z_over_p.size(); ++i) {
    if (std::isfinite(exact->x_over_a[i]) && std::isfinite(exact->sigma_z_over_p[i]))
      s.xy.emplace_back(exact->x_over_a[i], exact->sigma_z_over_p[i]);
  }
  panel.series.push_back(std::move(s));
  return panel;
}

/// The exact curve's peak (x, y), if a panel has an exact curve.
std::optional<std::pair<double, double>> exact_peak(const std::vector<Panel>& panels) {
  for (const auto& panel : panels) {
    for (const auto& s : panel.series) {
      if (s.title != "exact" || s.xy.empty())
        continue;
      return *std::max_element(s.xy.begin(), s.xy.end(),
                               [](const auto& a, const auto& b) { return a.second < b.second; });
    }
  }
  return std::nullopt;
}

/// The Steuermann peak sits in a narrow band near the contact edge, too small to judge at the
/// scale of the whole profile: a panel of the fine-mesh curves of every option set around the
/// exact peak (x within 0.03 of it, y from 80 % to 110 % of it).
std::optional<Panel> peak_zoom_panel(const std::vector<Panel>& panels) {
  const auto peak = exact_peak(panels);
  if (!peak || !(peak->second > 0))
    return std::nullopt;
  static constexpr std::array<const char*, 6> kColours{"#1b9e77", "#d95f02", "#7570b3",
                                                       "#e7298a", "#66a61e", "#e6ab02"};
  Panel zoom{"zoom at the peak (F mesh)",
             "x / b",
             "-sigma_z / p",
             false,
             std::pair(peak->first - 0.03, peak->first + 0.03),
             {},
             std::pair(0.8 * peak->second, 1.1 * peak->second)};
  std::size_t k = 0;
  for (const auto& panel : panels) {
    for (const auto& s : panel.series) {
      if (s.title != std::string(schema::to_string(kFinestMesh)))
        continue;
      Series copy = s;
      copy.title = panel.title;
      copy.color = kColours[k++ % kColours.size()];
      zoom.series.push_back(std::move(copy));
    }
  }
  for (const auto& s : panels.front().series) {
    if (s.title == "exact")
      zoom.series.push_back(s);
  }
  return zoom;
}

Figure profile_figure(const ResultsIndex& index, const Gnuplot* gnuplot, const fs::path& work,
                      const fs::path& out_root, const StudyFigure4& study_panel,
                      schema::Element element) {
  const ProblemId id = study_panel.problem;
  const schema::Quantity quantity = schema::Quantity::sigma_c;
  Figure fig{
      FigureKind::profile,
      id,
      quantity,
      fmt::format("figures/profile_{}_{}.png", schema::to_string(id), schema::to_string(element)),
      {},
      {},
      false,
      {}};
  const Slot slot{id, quantity, element};
  std::vector<Panel> panels;
  bool any_exact = false, any_missing_exact = false;
  for (const auto& cls : coincidence_classes(index, all_options(), {slot})) {
    bool has_exact = false;
    Panel panel = profile_panel(index, cls, slot, has_exact);
    if (panel.series.empty())
      continue;
    any_exact = any_exact || has_exact;
    any_missing_exact = any_missing_exact || !has_exact;
    panels.push_back(std::move(panel));
  }
  if (panels.empty())
    return fig;
  // One x-range for every panel, so that the panels compare at a glance.
  std::vector<Series> every;
  for (const auto& panel : panels)
    every.insert(every.end(), panel.series.begin(), panel.series.end());
  const auto shared = profile_range(every);
  for (auto& panel : panels)
    panel.xrange = shared;
  const schema::LengthScale scale = length_scale(index.problem(id));
  if (scale == schema::LengthScale::punch_half_width_b) {  // the rounded punch's edge peak
    if (auto zoom = peak_zoom_panel(panels))
      panels.push_back(std::move(*zoom));
  }
  fig.caption_md = fmt::format(
      "The study's Figure 4{} for {} elements: −σ<sub>z</sub>/p along z = 0 on the C, M and F "
      "meshes{}, one panel per option set ({}).",
      fmt::format(fmt::runtime(study_panel.caption), schema::label(id)), schema::to_string(element),
      any_exact ? " against the exact curve (black, dashed)" : "",
      fmt::format("x over {}", schema::label(scale)));
  if (any_missing_exact) {
    fig.notes.push_back(
        any_exact ? "some panels have no exact curve: their cases carry no `exact_profile`."
                  : "no exact curve: the results file carries no `exact_profile` for these cases.");
  }
  if (gnuplot != nullptr) {
    draw(*gnuplot, work, out_root, fig,
         fmt::format("{} {}: -sigma_z/p on z = 0 (C, M, F){}", plain_label(schema::label(id)),
                     schema::to_string(element), any_exact ? " and exact" : ""),
         panels, 3, 520, 380);
  }
  return fig;
}

}  // namespace

std::vector<ObservedOrderEntry> observed_orders(const ResultsIndex& index) {
  std::vector<ObservedOrderEntry> orders;
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<schema::Element>()) {
        const Slot slot{p->id, q.quantity, element};
        for (const auto& cls : coincidence_classes(index, all_options(), {slot})) {
          const RowPoints pts = row_points(index, *class_row(index, cls, slot), p->singular);
          orders.push_back({p->id, q.quantity, element, cls.label(), observed_order(pts.points),
                            p->singular, pts.relative_h, pts.round_off});
        }
      }
    }
  }
  return orders;
}

FigureSet render_figures(const ResultsIndex& index, const fs::path& out_root,
                         const FigureOptions& options) {
  FigureSet set;
  const auto gnuplot = find_gnuplot(options.gnuplot_program);
  if (!gnuplot) {
    set.unavailable = fmt::format("`{}` with a PNG terminal was not found, so no figure was drawn",
                                  options.gnuplot_program);
  }
  std::optional<ScratchDir> work;
  if (gnuplot)
    work.emplace();
  const fs::path work_path = work ? work->path() : fs::path();
  const Gnuplot* g = gnuplot ? &*gnuplot : nullptr;
  for (const auto& study_panel : kFigure4) {
    if (index.problem(study_panel.problem) == nullptr)
      continue;
    for (const auto element : schema::values<schema::Element>()) {
      Figure f = profile_figure(index, g, work_path, out_root, study_panel, element);
      if (!f.caption_md.empty())
        set.figures.push_back(std::move(f));
    }
  }
  const auto elements = schema::values<schema::Element>();
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      const bool any = std::any_of(elements.begin(), elements.end(), [&](schema::Element e) {
        return index.has(p->id, q.quantity, e);
      });
      if (any)
        set.figures.push_back(convergence_figure(index, g, work_path, out_root, *p, q, set.orders));
    }
  }
  return set;
}

std::string figures_section(const FigureSet& set) {
  if (set.figures.empty())
    return {};
  std::string out = "## Figures\n\n";
  if (!set.unavailable.empty())
    out += fmt::format("**No figures:** {}.\n\n", set.unavailable);
  std::optional<FigureKind> kind;
  for (const auto& f : set.figures) {
    if (f.kind != kind) {
      kind = f.kind;
      out += f.kind == FigureKind::profile
                 ? "### Contact stress along z = 0 (the study's Figure 4)\n\n"
                 : "### Error against element size, with the observed order\n\n";
    }
    if (f.produced) {
      const std::string alt =
          f.problem && f.quantity
              ? fmt::format("{} {}", schema::to_string(*f.problem), schema::to_string(*f.quantity))
              : std::string();
      out += fmt::format("![{}]({})\n\n", alt, f.file);
    } else if (set.unavailable.empty()) {
      out += fmt::format("*(figure not drawn: {})*\n\n",
                         f.error.empty() ? "nothing to plot" : f.error);
    }
    out += f.caption_md + "\n";
    if (f.kind == FigureKind::convergence) {
      std::string list;
      for (const auto& o : set.orders) {
        if (o.problem != f.problem || o.quantity != f.quantity)
          continue;
        list += fmt::format("{}{} {}: {}", list.empty() ? "" : "; ", schema::to_string(o.element),
                            o.option_label, order_text(o.order, o.singular, o.round_off, true));
      }
      if (!list.empty())
        out += fmt::format("Observed: {}.\n", list);
    }
    for (const auto& n : f.notes)
      out += fmt::format("*Note: {}*\n", n);
    out += "\n";
  }
  return out;
}

}  // namespace cs::reports

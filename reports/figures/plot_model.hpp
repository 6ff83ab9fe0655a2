#pragma once
// The one plot model of the report: a figure is panels of series of (x, y) points, with axis
// scales, labels, marks and key placement. Every figure builds one and hands it to the one
// gnuplot writer (figures/gnuplot.hpp). Text may hold the vocabulary's Markdown labels
// ("H<sub>p</sub>"): the writer prints them as plain text.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "schema/case_axes.hpp"

namespace cs::reports {

enum class Scale { linear, log };
/// How a series is drawn: a line, a line with symbols, symbols, open circles, or bars.
enum class Mark { line, line_points, points, open_points, bars };
/// Where each panel's key goes: below the panel (the canvas grows with it) or inside.
enum class KeyPlace { below, inside };

using Points = std::vector<std::pair<double, double>>;

struct PlotSeries {
  std::string title;   ///< empty: not in the key
  std::string colour;  ///< "#rrggbb"
  Mark mark = Mark::line;
  int dash = 1;        ///< gnuplot dash type: 1 solid, 2 dashed, 3 dotted, 4 dash-dotted
  int point = 7;       ///< gnuplot point type
  double width = 1.5;  ///< line width
  Points xy = {};      ///< a NaN point breaks the line
};

/// A plain line of one colour through `xy` (an exact curve, a reference line or slope).
inline PlotSeries line_series(std::string title, std::string colour, Points xy, int dash = 1,
                              double width = 1.5) {
  return {std::move(title), std::move(colour), Mark::line, dash, 7, width, std::move(xy)};
}

struct PlotAxis {
  std::string label;
  Scale scale = Scale::linear;
  std::optional<std::pair<double, double>> range = {};    ///< none: from the data
  std::vector<std::pair<double, std::string>> tics = {};  ///< none: automatic (1-2-5 on short logs)
  bool reversed = false;
};

/// A vertical line across a panel, labelled (e.g. a parameter's default value).
struct VerticalMark {
  double x = 0.0;
  std::string label;
};

/// A text at a data position (e.g. the ratio above a bar), on an opaque box.
struct PlotLabel {
  double x = 0.0, y = 0.0;
  std::string text;
};

struct PlotPanel {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series = {};
  std::vector<VerticalMark> marks = {};
  std::vector<PlotLabel> labels = {};
  double bar_width = 0.0;     ///< in x units, for Mark::bars
  bool equal_aspect = false;  ///< one unit of x as long as one of y (a mesh)
};

/// The points of every series of `panel`, in order.
inline Points points_of(const PlotPanel& panel) {
  Points out;
  for (const auto& s : panel.series)
    out.insert(out.end(), s.xy.begin(), s.xy.end());
  return out;
}

struct Plot {
  std::string title{};
  std::vector<PlotPanel> panels{};
  int columns = 2;
  int panel_width = 560, panel_height = 420;  ///< pixels, without the key
  KeyPlace key = KeyPlace::below;
  int key_columns = 2;
};

/// What a figure of the report shows.
enum class FigureKind { profile, convergence, sweep, bench, mesh };

/// One figure of the report, as the pages link it.
struct Figure {
  Figure() = default;
  Figure(FigureKind kind, std::string file, std::optional<schema::ProblemId> problem = {})
      : kind(kind), problem(problem), file(std::move(file)) {}
  FigureKind kind = FigureKind::profile;
  std::optional<schema::ProblemId> problem;  ///< the problem page that embeds it; none: no page
  std::string file;  ///< relative to the report directory, e.g. "figures/profile_H_p_Q4.png"
  std::string caption_md;
  std::vector<std::string> notes;  ///< what the figure leaves out, and why
  bool produced = false;           ///< the PNG was written
  std::string error;               ///< why not, when not
};

/// The figures of one kind of section, or why none could be drawn.
struct FigureSet {
  std::vector<Figure> figures;
  std::string unavailable;  ///< non-empty when no figure could be drawn (e.g. no gnuplot)
};

struct FigureOptions {
  std::string gnuplot_program = "gnuplot";  ///< the gnuplot to run (found on PATH)
};

/// A qualitative palette of 15 distinguishable colours; `i` wraps around.
std::string palette_colour(std::size_t i);

}  // namespace cs::reports

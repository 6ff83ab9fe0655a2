#pragma once
// The one writer of the plot model (figures/plot_model.hpp): a gnuplot script and one data file
// per series in a scratch directory (removed afterwards), run through platform/child_process on
// Debian's gnuplot (pngcairo, else the libgd png terminal).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "reports/figures/plot_model.hpp"

namespace cs::reports {

/// A usable gnuplot: the program and the PNG terminal it offers.
struct Gnuplot {
  std::string program;   ///< as given, e.g. "gnuplot" (found on PATH)
  std::string terminal;  ///< "pngcairo" or "png"
};

/// Probes `program`: nullopt when it cannot be run or offers neither PNG terminal.
std::optional<Gnuplot> find_gnuplot(const std::string& program = "gnuplot");

/// The plain text of a Markdown label, as gnuplot prints it: <sub>x</sub> -> _x,
/// <sup>x</sup> -> ^x, ′ -> ', any other tag dropped ("P′<sub>p</sub>" -> "P'_p").
std::string plain_label(std::string_view markdown);

/// Draws plots as PNG files. Never throws for a plotting failure: it returns why.
class GnuplotWriter {
 public:
  explicit GnuplotWriter(const FigureOptions& options = {});
  ~GnuplotWriter();
  GnuplotWriter(const GnuplotWriter&) = delete;
  GnuplotWriter& operator=(const GnuplotWriter&) = delete;
  /// Empty when gnuplot can draw; else a sentence saying why no figure can be drawn.
  const std::string& unavailable() const { return unavailable_; }
  /// Draws `plot` into `out_root`/`figure.file` and records the outcome in `figure`. Safe to call
  /// from several threads at once for figures of different files.
  void draw(const Plot& plot, const std::filesystem::path& out_root, Figure& figure) const;
  /// draw(plots[i], out_root, figures[i]) for every i, the figures shared among as many threads
  /// as this process has cores (each a gnuplot of its own): the same files and outcomes as one by
  /// one. plots and figures have the same size.
  void draw_all(const std::vector<Plot>& plots, const std::filesystem::path& out_root,
                std::vector<Figure>& figures) const;

 private:
  /// Writes the script and data of `plot`, runs gnuplot; "" on success, else why not.
  std::string run_script(const Plot& plot, const std::filesystem::path& png) const;
  std::optional<Gnuplot> gnuplot_;
  std::filesystem::path work_;  ///< scratch directory for scripts and data, removed afterwards
  std::string unavailable_;
};

/// Draws plots[i] into `out_root`/figures[i].file (GnuplotWriter::draw_all) and returns the
/// figures as a set, which says why none could be drawn when gnuplot cannot draw.
FigureSet draw_figures(const std::vector<Plot>& plots, std::vector<Figure> figures,
                       const std::filesystem::path& out_root, const FigureOptions& options);

}  // namespace cs::reports

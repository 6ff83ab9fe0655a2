#pragma once
// The report's figures, drawn by gnuplot as PNG files under DIR/figures/ and embedded in the
// Markdown with relative links:
//  - the study's Figure 4: -sigma_z/p along z = 0 for C, M and F against the exact curve, for
//    H_p and S_1_3, one panel per option set (from each case's `profile`; the exact curve from
//    the case's optional `exact_profile`);
//  - for every problem and quantity, log-log |error| (%) against element size h per option set,
//    with the observed order (least-squares slope) in the legend; for the singular flat punch,
//    the edge stress itself against h.
// Data and scripts go to a temporary directory, removed afterwards.

#include <filesystem>
#include <string>
#include <vector>

#include "reports/observed_order.hpp"
#include "reports/results_index.hpp"

namespace cs::reports {

/// One figure of the report.
struct Figure {
  std::string kind;      ///< "profile" | "convergence"
  std::string problem;   ///< results.json problem id
  std::string quantity;  ///< results.json quantity name
  std::string file;      ///< relative to the report directory, e.g. "figures/profile_H_p_Q4.png"
  std::string caption_md;
  std::vector<std::string> notes;  ///< what the figure lacks (e.g. no exact curve)
  bool produced = false;           ///< the PNG was written
  std::string error;               ///< why not, when not
};

/// The observed order of one option set on one problem, quantity and element.
struct ObservedOrderEntry {
  std::string problem, quantity, element, option_label;
  std::optional<double> order;
  bool relative_h = false;  ///< element_size_h missing: h taken as 1, 1/2, 1/4
};

/// The figures of a report and the observed orders shown in them.
struct FigureSet {
  std::vector<Figure> figures;
  std::vector<ObservedOrderEntry> orders;
  std::string unavailable;  ///< non-empty when no figure could be drawn (e.g. no gnuplot)
};

struct FigureOptions {
  std::string gnuplot_program = "gnuplot";  ///< the gnuplot to run (found on PATH)
};

/// The observed orders of every baseline option set (no plotting; used by render_figures).
std::vector<ObservedOrderEntry> observed_orders(const ResultsIndex& index);

/// Draws every figure into `out_root`/figures/. Never throws for a plotting failure: a figure
/// that could not be drawn carries its error, and the report says so.
FigureSet render_figures(const ResultsIndex& index, const std::filesystem::path& out_root,
                         const FigureOptions& options = {});

/// Section 4 of the report (empty when there is nothing to plot).
std::string figures_section(const FigureSet& figures);

}  // namespace cs::reports

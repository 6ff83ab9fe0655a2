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
#include <optional>
#include <string>
#include <vector>

#include "reports/figures/observed_order.hpp"
#include "reports/results/results_index.hpp"

namespace cs::reports {

/// What a figure shows.
enum class FigureKind {
  profile,      ///< -sigma_z/p along z = 0 (the study's Figure 4)
  convergence,  ///< |error| (or the singular value) against element size
  bench,        ///< benchmark times (figures/bench_figure.hpp)
  mesh,         ///< a model's mesh (figures/mesh_figure.hpp, the study's Figure 3)
};

/// One figure of the report.
struct Figure {
  FigureKind kind = FigureKind::profile;
  std::optional<schema::ProblemId> problem;  ///< none for the bench chart
  std::optional<schema::Quantity> quantity;  ///< none for the bench chart
  std::string file;  ///< relative to the report directory, e.g. "figures/profile_H_p_Q4.png"
  std::string caption_md;
  std::vector<std::string> notes;  ///< what the figure lacks (e.g. no exact curve)
  bool produced = false;           ///< the PNG was written
  std::string error;               ///< why not, when not
};

/// The observed order of one option set on one problem, quantity and element.
struct ObservedOrderEntry {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::Element element = schema::Element::Q4;
  std::string option_label;
  std::optional<double> order;
  bool singular = false;    ///< a slope of the value itself (the flat punch), not an order
  bool relative_h = false;  ///< element_size_h missing: h taken as 1, 1/2, 1/4
  bool round_off = false;   ///< errors at round-off (schema::kErrorNoiseFloorPercent): no order
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

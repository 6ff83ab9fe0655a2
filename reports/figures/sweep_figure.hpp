#pragma once
// The figures of the report's sweep section, DIR/figures/sweep_KEY.png: one per swept key, one
// panel per problem, stress quantity and element on the finest mesh swept, |error| (%) against
// the swept value (log axes where the values span two decades or more), one curve per option
// set in its colour; a case that did not converge is an open circle; the problem's default
// value is a vertical line labelled "default". Errors below schema::kErrorNoiseFloorPercent
// (exact to round-off) are left out of the log plot, and the figure's notes say so.

#include <filesystem>
#include <string>
#include <vector>

#include "reports/figures/plot_model.hpp"
#include "reports/findings/parameter_series.hpp"

namespace cs::reports {

/// One panel of a sweep figure: the series of one problem, quantity, mesh and element.
struct SweepPanel {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::MeshLevel mesh = schema::MeshLevel::F;
  schema::Element element = schema::Element::Q4;
  SeriesRefs series;
};

/// The panels of a key's series (sweep_series), in their order: the finest mesh swept of each
/// problem and element, every stress quantity (not the contact half-width, graded apart).
std::vector<SweepPanel> sweep_panels(const std::vector<ParameterSeries>& series);

/// The plot of a key's panels; what it leaves out goes to `figure`'s notes.
Plot sweep_plot(const schema::ResultsDocument& doc, const std::string& key,
                const std::vector<SweepPanel>& panels, Figure& figure);

/// The relative file of a key's figure: "figures/sweep_fkn.png".
std::string sweep_figure_file(const std::string& key);

/// Draws one figure per swept key into `out_root`/figures/. Never throws for a plotting
/// failure: a figure carries its error, or the set says why none could be drawn (no gnuplot).
FigureSet render_sweep_figures(const schema::ResultsDocument& doc,
                               const std::filesystem::path& out_root,
                               const FigureOptions& options = {});

}  // namespace cs::reports

#pragma once
// The figures of the report's sweep section, drawn by gnuplot as DIR/figures/sweep_KEY.png: one
// per swept key, one panel per problem, stress quantity and element on the finest mesh swept,
// |error| (%) against the swept value (log axes where the values span two decades or more), one
// curve per option set; a case that did not converge is drawn as an open circle.

#include <filesystem>
#include <string>
#include <vector>

#include "reports/figures/figures.hpp"
#include "reports/findings/sweep_series.hpp"

namespace cs::reports {

/// One panel of a sweep figure: the series of one problem, quantity, mesh and element.
struct SweepPanel {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::MeshLevel mesh = schema::MeshLevel::F;
  schema::Element element = schema::Element::Q4;
  std::vector<const SweepSeries*> series;
};

/// The panels of a key's series, in document order: the finest mesh swept of each problem and
/// element, every stress quantity (not the contact half-width, graded apart).
std::vector<SweepPanel> sweep_panels(const std::vector<SweepSeries>& series);

/// The relative file of a key's figure: "figures/sweep_fkn.png".
std::string sweep_figure_file(const std::string& key);

/// Draws one figure per swept key into `out_root`/figures/. Never throws for a plotting
/// failure: a figure carries its error, or the set says why none could be drawn (no gnuplot).
FigureSet render_sweep_figures(const schema::ResultsDocument& doc,
                               const std::filesystem::path& out_root,
                               const FigureOptions& options = {});

}  // namespace cs::reports

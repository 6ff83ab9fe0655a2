#pragma once
// The sweep section's figures, DIR/figures/sweep_KEY.png: per panel |error| (%) against the swept
// value (log axes over two decades or more), one curve per option set, open circles where a case
// did not converge, the problem's default value marked. Errors below
// schema::kErrorNoiseFloorPercent (exact to round-off) are left out of the log plot, and the
// figure's notes say so.

#include <filesystem>
#include <string>
#include <vector>

#include "reports/figures/plot_model.hpp"
#include "reports/findings/parameter_series.hpp"

namespace cs::reports {

/// The panels of a key's series (sweep_series), in their order: per problem, quantity and
/// element, the series the section shows (shown_in_answers).
std::vector<SeriesRefs> sweep_panels(const std::vector<ParameterSeries>& series);

/// The plot of a key's panels; what it leaves out goes to `figure`'s notes.
Plot sweep_plot(const schema::ResultsDocument& doc, const std::string& key,
                const std::vector<SeriesRefs>& panels, Figure& figure);

/// The relative file of a key's figure: "figures/sweep_fkn.png". Letters, digits and '_' stand
/// as they are, any other byte as '-' and its two hex digits ("a.b" -> "sweep_a-2eb.png"), so two
/// keys never share a file (the figures are drawn side by side).
std::string sweep_figure_file(const std::string& key);

/// Draws one figure per swept key into `out_root`/figures/. Never throws for a plotting
/// failure: a figure carries its error, or the set says why none could be drawn (no gnuplot).
FigureSet render_sweep_figures(const schema::ResultsDocument& doc,
                               const std::filesystem::path& out_root,
                               const FigureOptions& options = {});

}  // namespace cs::reports

#pragma once
// The figures of the problem pages, under DIR/figures/:
//  - the study's Figure 4 for every problem with surface profiles, per element:
//    -sigma_z/p along z = 0 on C, M and F against the exact curve, one panel per option set,
//    and a zoom at the exact peak showing C, M and F of every option set;
//  - per problem and quantity, log-log |error| (%) against element size h per option set, the
//    legend giving the guarded observed order of grading::observed_order (or why there is
//    none); for the singular flat punch, the edge stress itself and its divergence exponent.
// One colour per option set (its place in all_options()), the same in every panel and figure;
// the mesh by the line's dashes (C dotted, M dashed, F solid).

#include <filesystem>
#include <string>

#include "reports/facts/row_facts.hpp"
#include "reports/figures/plot_model.hpp"

namespace cs::reports {

/// The length a problem's positions and sizes are over (its record's length_scale; a record
/// written before length scales were recorded: the contact half-width a).
schema::LengthScale length_scale_of(const ResultsIndex& index, schema::ProblemId id);

/// The colour of an option set: one per entry of all_options().
std::string option_colour(const Option& option);

/// The profile figure of a problem and element (empty panels: no profile); its notes in `figure`.
Plot profile_plot(const ResultsIndex& index, schema::ProblemId problem, schema::Element element,
                  Figure& figure);

/// The convergence figure of a problem's quantity; its notes in `figure`.
Plot convergence_plot(const ResultsIndex& index, const std::vector<RowFacts>& rows,
                      const std::vector<DivergenceFacts>& singular,
                      const schema::ProblemRecord& problem, const schema::QuantityDefinition& q,
                      Figure& figure);

/// Draws every figure into `out_root`/figures/. Never throws for a plotting failure: a figure
/// that could not be drawn carries its error, and the set says why when none could be.
FigureSet render_figures(const ResultsIndex& index, const std::filesystem::path& out_root,
                         const FigureOptions& options = {});

}  // namespace cs::reports

#include "reports/figures/mesh_figure.hpp"

#include <cmath>

#include <fmt/format.h>

#include "reports/figures/gnuplot.hpp"
#include "reports/render/template_text.hpp"
#include "reports/results/exported_models.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

/// Element outlines of one body: each ring closed, a break between elements.
Points outlines(const ExportedModel& m, int body) {
  Points out;
  for (const auto& e : m.elements) {
    if (e.body != body)
      continue;
    for (std::size_t i = 0; i <= e.ring.size(); ++i) {
      const auto& p = m.nodes.at(e.ring[i % e.ring.size()]);
      out.emplace_back(p[0], p[1]);
    }
    out.emplace_back(NAN, NAN);
  }
  return out;
}

/// The whole model beside a zoom on the contact (twice the contact half-width across); z
/// points down, into the block.
Plot mesh_plot(const ExportedModel& m) {
  Plot plot{.panel_width = 620, .panel_height = 500};
  PlotPanel whole{m.name + ": the whole model", {"x"}, {"z (into the block)"}};
  whole.y.reversed = true;
  whole.equal_aspect = true;
  whole.series = {line_series("indented block", "#1f77b4", outlines(m, 0), 1, 0.6),
                  line_series("indenter", "#d62728", outlines(m, 1), 1, 0.6)};
  PlotPanel zoom = whole;
  zoom.title = fmt::format("{}: near the contact (a = {:.4g})", m.name, m.a);
  zoom.x.range = std::pair(0.0, 2.0 * m.a);
  zoom.y.range = std::pair(-0.75 * m.a, 1.25 * m.a);
  plot.panels = {whole, zoom};
  return plot;
}

}  // namespace

FigureSet render_mesh_figures(const fs::path& export_dir, const fs::path& out_root,
                              const FigureOptions& options) {
  const std::vector<ExportedModel> models = read_exported_models(export_dir);
  std::vector<Plot> plots;
  std::vector<Figure> figures;
  for (const auto& m : models) {
    Figure f(FigureKind::mesh, "figures/mesh_" + m.name + ".png");
    TemplateData caption("name", m.name);
    caption.set("block", std::to_string(m.block_elements));
    caption.set("indenter", std::to_string(static_cast<int>(m.elements.size()) - m.block_elements));
    f.caption_md = figure_text("mesh", caption);
    // The problem of "H_p_C_Q4": the name without its mesh and element, for its problem page.
    const std::size_t cut = m.name.rfind('_', m.name.rfind('_') - 1);
    f.problem = cut == std::string::npos
                    ? std::nullopt
                    : schema::try_parse<schema::ProblemId>(m.name.substr(0, cut));
    plots.push_back(mesh_plot(m));
    figures.push_back(std::move(f));
  }
  return draw_figures(plots, std::move(figures), out_root, options);
}

std::string mesh_figures_section(const FigureSet& figures) {
  if (figures.figures.empty())
    return {};
  return render_template(templates::mesh_figures,
                         TemplateData("figures", template_list(figures.figures, figure_data)));
}

}  // namespace cs::reports

#pragma once
// Figure 3: pictures of the meshes, drawn from the models `contact-suite export` writes
// (docs/import-export.md: models/<model>/nodes.csv, elements.csv, model.csv). The report does
// not build meshes; it draws what the suite exported.

#include <filesystem>
#include <string>

#include "reports/figures/figures.hpp"

namespace cs::reports {

/// Draws each model under `export_dir`/models/ into `out_root`/figures/mesh_<model>.png: the
/// whole model beside a zoom on the contact (twice the contact half-width across), the block
/// and the indenter in two colours. Every model is read and checked before anything is drawn;
/// a directory that is not an export, or a malformed file, is a ReportError naming it. A
/// figure gnuplot could not draw carries its error, as render_figures' do.
FigureSet render_mesh_figures(const std::filesystem::path& export_dir,
                              const std::filesystem::path& out_root,
                              const FigureOptions& options = {});

/// The section "The meshes (Figure 3)" (empty when there is no figure).
std::string mesh_figures_section(const FigureSet& figures);

}  // namespace cs::reports

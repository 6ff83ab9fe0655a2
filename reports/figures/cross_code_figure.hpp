#pragma once
// The cross-code figure: the contact pressure along the surface on the fine mesh, p(x)/p
// against x/a (x/b for S), for H_p and S(1/3), one curve per solver, against the exact one
// (-sigma_z/p on z = 0, which is the contact pressure inside the contact and 0 outside). One
// panel per problem and element. Each panel shows one option set: the first, in the
// vocabulary's order, that every solver solved on F with a pressure profile (else the first
// any other solver ran, its missing curves named in the notes).

#include <filesystem>
#include <vector>

#include "reports/facts/cross_code_profiles.hpp"
#include "reports/figures/plot_model.hpp"

namespace cs::reports {

/// Draws the figure into `out_root`/figures/cross_code_profiles.png; an empty Figure list when
/// there are no panels. Never throws for a plotting failure (the Figure carries the error).
std::vector<Figure> render_cross_code_figure(const ResultsIndex& index,
                                             const std::filesystem::path& out_root,
                                             const FigureOptions& options = {});

}  // namespace cs::reports

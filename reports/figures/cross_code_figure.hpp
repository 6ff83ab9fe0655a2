#pragma once
// The cross-code figure: the contact pressure along the surface on the fine mesh, p(x)/p
// against x/a (x/b for S), for H_p and S(1/3), one curve per solver, against the exact one
// (-sigma_z/p on z = 0, which is the contact pressure inside the contact and 0 outside). One
// panel per problem and element. Each panel shows one option set: the first, in the
// vocabulary's order, that every solver solved on F with a pressure profile (else the first
// any other solver ran, its missing curves named in the notes).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "reports/figures/figures.hpp"
#include "reports/results/results_index.hpp"

namespace cs::reports {

/// One curve of a panel.
struct ProfileCurve {
  std::string title;  ///< "ours", "CalculiX", "exact"
  std::vector<std::pair<double, double>> xy;
};

/// One panel: a problem and element on the fine mesh, one option set.
struct CrossCodePanel {
  schema::ProblemId problem = schema::ProblemId::H_p;
  schema::Element element = schema::Element::Q4;
  Option option;
  std::vector<ProfileCurve> curves;  ///< one per solver that has a profile, then the exact one
  std::vector<std::string> missing;  ///< solvers without a profile on F (their case's status)
};

/// The problems of the figure: H_p and S(1/3).
std::vector<schema::ProblemId> cross_code_figure_problems();

/// The panels (no plotting): every problem of the figure and element with a case of another
/// solver on F.
std::vector<CrossCodePanel> cross_code_profile_panels(const ResultsIndex& index);

/// Draws the figure into `out_root`/figures/cross_code_profiles.png; an empty Figure list when
/// there are no panels. Never throws for a plotting failure (the Figure carries the error).
std::vector<Figure> render_cross_code_figure(const ResultsIndex& index,
                                             const std::filesystem::path& out_root,
                                             const FigureOptions& options = {});

}  // namespace cs::reports

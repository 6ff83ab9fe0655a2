#pragma once
// The contact-pressure profiles of the cross-code figure: for H_p and S(1/3), per element, on
// the fine mesh, one curve per solver, against the exact one (-sigma_z/p on z = 0, which is
// the contact pressure inside the contact and 0 outside). Each panel shows one option set: the
// first, in the vocabulary's order, that every solver solved on F with a pressure profile (else
// the first any other solver ran, its missing curves named).

#include <string>
#include <utility>
#include <vector>

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

}  // namespace cs::reports

#include "reports/tables/solver_option_mapping.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {

std::string option_mapping_markdown(const std::vector<SolverOptionMapping>& mappings,
                                    const std::vector<std::string>& solvers) {
  std::string out;
  for (const auto& s : solvers) {
    MarkdownTable table(
        {"study option", fmt::format("{} runs", solver_display_name(s)), "fidelity", "why"});
    for (const auto& m : mappings) {
      if (m.solver == s)
        table.add_row({m.study_option, m.target.empty() ? kMissing : m.target, m.fidelity, m.note});
    }
    if (table.n_rows() == 0)
      continue;
    out += fmt::format(
        "#### The study's options in {}\n\nEach case of {} ran the study's option mapped to the "
        "solver's own as below (from its adapter; `contact-suite list` prints the same).\n\n{}\n",
        solver_display_name(s), solver_display_name(s), table.render());
  }
  return out;
}

}  // namespace cs::reports

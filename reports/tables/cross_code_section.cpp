#include "reports/tables/cross_code_section.hpp"

#include <map>

#include <fmt/format.h>

#include "reports/tables/cross_code_appendix.hpp"
#include "reports/tables/cross_code_cost.hpp"
#include "reports/tables/cross_code_grade_table.hpp"
#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using Counts = std::map<schema::CaseStatus, int>;

std::string counts_text(const Counts& c) {
  std::string out;
  for (const auto s : schema::values<schema::CaseStatus>()) {
    const auto it = c.find(s);
    if (it != c.end() && it->second > 0)
      out += fmt::format("{}{} {}", out.empty() ? "" : ", ", it->second, schema::label(s));
  }
  return out.empty() ? std::string(kMissing) : out;
}

std::string tally_markdown(const std::map<std::string, GradeTally>& tally,
                           const std::vector<std::string>& solvers) {
  const std::vector<std::string> classes{"e, c", "e", "g", "s", "u", "no grade"};
  std::vector<std::string> header{"Solver", "rows"};
  header.insert(header.end(), classes.begin(), classes.end());
  MarkdownTable table(header);
  for (const auto& s : solvers) {
    const auto it = tally.find(s);
    if (it == tally.end())
      continue;
    std::vector<std::string> cells{solver_display_name(s), std::to_string(it->second.rows)};
    for (const auto& c : classes) {
      const auto n = it->second.by_class.find(c);
      cells.push_back(std::to_string(n == it->second.by_class.end() ? 0 : n->second));
    }
    table.add_row(std::move(cells));
  }
  if (table.n_rows() == 0)
    return {};
  return "Fine-mesh grades of the rows of Table 2′ that every solver ran (both elements; *no "
         "grade*: a case not converged, timed out or failed):\n\n" +
         table.render() + "\n";
}

std::string figures_markdown(const std::vector<Figure>& figures) {
  std::string out;
  for (const auto& f : figures) {
    out += f.produced ? fmt::format("![{}]({})\n\n", "cross-code pressure profiles", f.file)
                      : fmt::format("*(figure not drawn: {})*\n\n", f.error);
    out += f.caption_md + "\n\n";
    for (const auto& n : f.notes)
      out += "- " + n + "\n";
    if (!f.notes.empty())
      out += "\n";
  }
  return out;
}

}  // namespace

std::string cross_code_outcome_markdown(const ResultsIndex& index) {
  std::string out;
  for (const auto& s : solvers_in(index)) {
    std::map<std::pair<int, schema::MeshLevel>, Counts> by_cell;
    std::map<int, std::string> labels;
    Counts total;
    for (std::size_t i = 0; i < index.problems().size(); ++i) {
      const auto id = index.problems()[i]->id;
      labels[static_cast<int>(i)] = std::string(schema::label(id));
      for (const auto& c : index.results().cases) {
        if (c.spec.problem != id || schema::solver_label(c.spec) != s ||
            c.spec.recovery != schema::Recovery::spr)
          continue;
        ++by_cell[{static_cast<int>(i), c.spec.mesh}][c.status];
        ++total[c.status];
      }
    }
    std::vector<std::string> header{"Problem"};
    for (const auto m : kMeshes)
      header.emplace_back(schema::to_string(m));
    MarkdownTable table(header);
    for (const auto& [i, label] : labels) {
      std::vector<std::string> cells{label};
      bool any = false;
      for (const auto m : kMeshes) {
        const auto it = by_cell.find({i, m});
        any = any || it != by_cell.end();
        cells.push_back(it == by_cell.end() ? std::string(kMissing) : counts_text(it->second));
      }
      if (any)
        table.add_row(std::move(cells));
    }
    out += fmt::format("**{}**: {} in all.\n\n{}\n", solver_display_name(s), counts_text(total),
                       table.render());
  }
  return out;
}

std::string cross_code_section(const ResultsIndex& index, const StudyReference& study,
                               const std::vector<Figure>& figures,
                               const std::vector<SolverOptionMapping>& mappings) {
  if (!is_cross_code(index))
    return {};
  const auto solvers = solvers_in(index);
  std::string names;
  for (std::size_t i = 0; i < solvers.size(); ++i)
    names += (i == 0                    ? ""
              : i + 1 == solvers.size() ? " and "
                                        : ", ") +
             solver_display_name(solvers[i]);
  std::string out = fmt::format(
      "## Cross-code comparison: {} beside the study's ANSYS\n\n"
      "The same cases (mesh, loads as consistent nodal forces, contact pair) solved by each "
      "solver and graded alike. Cases per solver, problem and mesh, by how they ended "
      "(a case that did not finish in its time limit is a *timeout*):\n\n{}",
      names, cross_code_outcome_markdown(index));
  out += tally_markdown(cross_code_grade_tally(index, study), solvers);
  std::string tables;
  for (const auto element : schema::values<schema::Element>()) {
    if (auto t = build_cross_code_grade_table(index, study, element))
      tables += t->markdown();
  }
  if (!tables.empty()) {
    out += fmt::format(
        "### Table 2′: grades side by side\n\nEach cell: the fine-mesh grade of {}, then the "
        "study's ANSYS cell of Table 2 (grades and markers as in Tables 2a/2b; a status with a "
        "mesh, e.g. *timeout (F)*, where a solver did not finish that mesh).\n\n{}",
        names, tables);
  }
  out += option_mapping_markdown(mappings, solvers);
  if (!figures.empty())
    out += "### Contact pressure per solver\n\n" + figures_markdown(figures);
  std::string cost;
  for (const auto& c : cross_code_cost(index))
    cost += c.markdown();
  if (!cost.empty()) {
    out +=
        "### Cost on the same cases\n\nWall time (sum over the cases) and peak memory (largest "
        "over the cases) of each solver on the cases both ran, as recorded in the results: ours "
        "builds a model once per problem, mesh and element and charges that to its first case, "
        "and its peak is the process's; another solver's wall time is its whole run of the "
        "case (input written, solver run, output read) and its peak that of its own process "
        "or ours, the larger. Ratios are the other solver's over ours; timeouts count with the "
        "time they took.\n\n" +
        cost;
  }
  std::string appendix;
  for (const auto& t : build_cross_code_appendix(index, study))
    appendix += t.markdown();
  if (!appendix.empty()) {
    out += fmt::format(
        "### Values per mesh and solver\n\nEach solver's value (its error) on C, M and F, and "
        "the study's ANSYS value on F.\n\n{}",
        appendix);
  }
  return out;
}

}  // namespace cs::reports

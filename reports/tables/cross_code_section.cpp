#include "reports/tables/cross_code_section.hpp"

#include <map>

#include <fmt/format.h>

#include "reports/render/template_text.hpp"
#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/cross_code_tables.hpp"
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

std::string tally_table(const std::map<std::string, GradeTally>& tally,
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
  return table.n_rows() == 0 ? std::string() : table.render();
}

/// "ours, calculix:hard-ss and X".
std::string names_of(const std::vector<std::string>& solvers, const char* last) {
  std::string out;
  for (std::size_t i = 0; i < solvers.size(); ++i)
    out += (i == 0 ? "" : i + 1 == solvers.size() ? last : ", ") + solver_display_name(solvers[i]);
  return out;
}

TemplateData figure_data(const Figure& f) {
  TemplateData d;
  d.set("produced", f.produced);
  d.set("file", f.file);
  d.set("error", f.error);
  d.set("caption", f.caption_md);
  d.set("notes", template_list(f.notes, [](const std::string& n) { return TemplateData(n); }));
  return d;
}

}  // namespace

std::string cross_code_outcome_markdown(const ResultsIndex& index) {
  std::string out;
  for (const auto& s : solvers_in(index)) {
    std::vector<std::string> header{"Problem"};
    for (const auto m : kMeshes)
      header.emplace_back(schema::to_string(m));
    MarkdownTable table(header);
    Counts total;
    for (const schema::ProblemRecord* p : index.problems()) {
      std::map<schema::MeshLevel, Counts> by_mesh;
      for (const auto& c : index.results().cases) {
        if (c.spec.problem != p->id || schema::solver_label(c.spec) != s ||
            c.spec.recovery != schema::Recovery::spr)
          continue;
        ++by_mesh[c.spec.mesh][c.status];
        ++total[c.status];
      }
      std::vector<std::string> cells{std::string(schema::label(p->id))};
      for (const auto m : kMeshes)
        cells.push_back(by_mesh.count(m) ? counts_text(by_mesh[m]) : std::string(kMissing));
      if (!by_mesh.empty())
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
  TemplateData d;
  d.set("names", names_of(solvers, " and "));
  d.set("order", names_of(solvers, ", ") + ", ANSYS");
  d.set("outcome", cross_code_outcome_markdown(index));
  d.set("tally", text_or_false(tally_table(cross_code_grade_tally(index, study), solvers)));
  std::vector<std::pair<std::string, std::string>> grades;
  for (const auto element : schema::values<schema::Element>()) {
    if (auto t = build_cross_code_grade_table(index, study, element))
      grades.emplace_back(schema::to_string(element), t->render());
  }
  const auto titled = [](const auto& item) {
    TemplateData t;
    t.set("title", item.first);
    t.set("table", item.second);
    return t;
  };
  d.set("has_grades", !grades.empty());
  d.set("grades", template_list(grades, titled));
  d.set("mapping", option_mapping_markdown(mappings, solvers));
  d.set("has_figures", !figures.empty());
  d.set("figures", template_list(figures, figure_data));
  std::vector<std::pair<std::string, std::string>> costs, appendix;
  for (const auto& c : cross_code_cost(index))
    costs.emplace_back(solver_display_name(c.solver), cost_table(c).render());
  for (const auto& [problem, table] : build_cross_code_appendix(index, study))
    appendix.emplace_back(schema::label(problem), table.render());
  d.set("has_costs", !costs.empty());
  d.set("costs", template_list(costs, titled));
  d.set("has_appendix", !appendix.empty());
  d.set("appendix", template_list(appendix, titled));
  return tidy_markdown(render_template(templates::cross_code_section, d));
}

}  // namespace cs::reports

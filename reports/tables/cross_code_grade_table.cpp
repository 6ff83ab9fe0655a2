#include "reports/tables/cross_code_grade_table.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

constexpr const char* kSeparator = " │ ";

/// The finest mesh of a row whose case did not converge, with its status: "timeout (F)".
std::optional<std::string> unfinished_status(const ResultsIndex& index,
                                             const schema::RowVerdict& row) {
  for (auto it = kMeshes.rbegin(); it != kMeshes.rend(); ++it) {
    const schema::CaseResult* c = index.case_of(row, *it);
    if (c != nullptr && c->status != schema::CaseStatus::converged)
      return fmt::format("{} ({})", schema::label(c->status), schema::to_string(*it));
  }
  return std::nullopt;
}

std::string ansys_cell(const StudyReference& study, const StudyRowKey& r, schema::Element element,
                       const Option& o) {
  const StudyGrade* g = study.find_grade(r.problem, r.study_row, element, o.algorithm, o.contact);
  return g == nullptr ? std::string("ANSYS ") + kMissing : "ANSYS " + g->cell();
}

}  // namespace

std::string solver_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row) {
  if (row == nullptr)
    return kMissing;
  const auto status = unfinished_status(index, *row);
  if (!row->grade && status)
    return *status;
  const std::string grade = format_grade_cell(index, row);
  // Graded on a coarser mesh because the finer one did not finish: say how it ended.
  return status && row->graded_mesh && *row->graded_mesh != kFinestMesh
             ? fmt::format("{}, {}", grade, *status)
             : grade;
}

std::optional<MarkdownTable> build_cross_code_grade_table(const ResultsIndex& index,
                                                          const StudyReference& study,
                                                          schema::Element element) {
  const auto solvers = solvers_in(index);
  std::vector<Option> options;
  const auto rows = grade_table_rows(index, study);
  for (const auto& r : rows) {
    if (!r.quantity)
      continue;
    for (const auto& o : cross_code_options(index, r.problem, *r.quantity, element)) {
      if (std::find(options.begin(), options.end(), o) == options.end())
        options.push_back(o);
    }
  }
  if (options.empty())
    return std::nullopt;
  std::sort(options.begin(), options.end(), [](const Option& a, const Option& b) {
    const auto& all = all_options();
    return std::find(all.begin(), all.end(), a) < std::find(all.begin(), all.end(), b);
  });
  std::vector<std::string> header{"Problem"};
  for (const auto& o : options)
    header.push_back(o.label());
  MarkdownTable t(header);
  for (const auto& r : rows) {
    if (!r.quantity || cross_code_options(index, r.problem, *r.quantity, element).empty())
      continue;
    std::vector<std::string> cells{r.label_md};
    for (const auto& o : options) {
      std::string cell;
      for (const auto& s : solvers)
        cell += solver_grade_cell(index, solver_row(index, s, r.problem, *r.quantity, element, o)) +
                kSeparator;
      cells.push_back(cell + ansys_cell(study, r, element, o));
    }
    t.add_row(std::move(cells));
  }
  return t;
}

std::string grade_class(const schema::RowVerdict* row) {
  if (row == nullptr || !row->grade || (row->graded_mesh && *row->graded_mesh != kFinestMesh))
    return "no grade";
  const std::string g(schema::to_string(*row->grade));
  return row->converging.value_or(false) && *row->grade == schema::Grade::e ? g + ", c" : g;
}

std::map<std::string, GradeTally> cross_code_grade_tally(const ResultsIndex& index,
                                                         const StudyReference& study) {
  std::map<std::string, GradeTally> out;
  const auto solvers = solvers_in(index);
  for (const auto& r : grade_table_rows(index, study)) {
    if (!r.quantity)
      continue;
    for (const auto element : schema::values<schema::Element>()) {
      for (const auto& o : cross_code_options(index, r.problem, *r.quantity, element)) {
        std::vector<const schema::RowVerdict*> rows;
        for (const auto& s : solvers)
          rows.push_back(solver_row(index, s, r.problem, *r.quantity, element, o));
        if (std::find(rows.begin(), rows.end(), nullptr) != rows.end())
          continue;  // not run by every solver: not a like-for-like count
        for (std::size_t i = 0; i < solvers.size(); ++i) {
          auto& tally = out[solvers[i]];
          ++tally.by_class[grade_class(rows[i])];
          ++tally.rows;
        }
      }
    }
  }
  return out;
}

}  // namespace cs::reports

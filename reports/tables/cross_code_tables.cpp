#include "reports/tables/cross_code_tables.hpp"

#include <algorithm>
#include <map>

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

std::string ansys_value(const StudyReference& study, const schema::RowVerdict& row) {
  const StudyMatch m = study.find_value(row.spec.problem, row.quantity, row.spec.element,
                                        row.spec.algorithm, row.spec.contact, kFinestMesh);
  return m.value == nullptr ? std::string(kMissing) : m.value->printed;
}

std::string exact_cell(const ResultsIndex& index,
                       const std::vector<const schema::RowVerdict*>& rows) {
  for (const auto* r : rows) {
    if (r == nullptr)
      continue;
    if (auto e = index.exact_of(*r))
      return format_value(*e);
  }
  return "∞";
}

using schema::CaseResult;

void add(CostLine& line, const CaseResult& ours, const CaseResult& other) {
  ++line.pairs;
  line.ours_seconds += ours.wall_seconds;
  line.other_seconds += other.wall_seconds;
  line.ours_peak_mb = std::max(line.ours_peak_mb, ours.peak_rss_mb);
  line.other_peak_mb = std::max(line.other_peak_mb, other.peak_rss_mb);
  if (other.status == schema::CaseStatus::converged)
    ++line.other_converged;
}

std::string ratio_text(const std::optional<double>& r) {
  return r ? fmt::format("{:.3g}", *r) : std::string(kMissing);
}

std::vector<std::string> cells(const CostLine& l) {
  return {l.label,
          std::to_string(l.pairs),
          std::to_string(l.other_converged),
          fmt::format("{:.3g}", l.ours_seconds),
          fmt::format("{:.3g}", l.other_seconds),
          ratio_text(l.time_ratio()),
          fmt::format("{:.0f}", l.ours_peak_mb),
          fmt::format("{:.0f}", l.other_peak_mb),
          ratio_text(l.memory_ratio())};
}

/// Our cases by same_case_key (one per key: the first, spr before other recoveries).
std::map<std::string, const CaseResult*> ours_by_key(const ResultsIndex& index) {
  std::map<std::string, const CaseResult*> out;
  for (const auto& c : index.results().cases) {
    if (schema::solver_label(c.spec) != builtin_solver_label())
      continue;
    auto [it, inserted] = out.emplace(same_case_key(c.spec), &c);
    if (!inserted && c.spec.recovery == schema::Recovery::spr &&
        it->second->spec.recovery != schema::Recovery::spr)
      it->second = &c;
  }
  return out;
}

CrossCodeCost compare(const ResultsIndex& index, const std::string& solver,
                      const std::map<std::string, const CaseResult*>& ours) {
  CrossCodeCost out;
  out.solver = solver;
  out.total.label = "all cases";
  out.total_both_converged.label = "cases both converged";
  std::map<std::pair<int, schema::MeshLevel>, CostLine> lines;
  std::map<schema::ProblemId, int> order;
  for (std::size_t i = 0; i < index.problems().size(); ++i)
    order[index.problems()[i]->id] = static_cast<int>(i);
  std::map<std::string, bool> seen;  // one pair per key (an other solver's recovery twin)
  for (const auto& c : index.results().cases) {
    if (schema::solver_label(c.spec) != solver)
      continue;
    const std::string key = same_case_key(c.spec);
    const auto it = ours.find(key);
    if (it == ours.end() || seen[key])
      continue;
    seen[key] = true;
    const int position = order.count(c.spec.problem) ? order[c.spec.problem] : 1000;
    CostLine& line = lines[{position, c.spec.mesh}];
    line.label =
        fmt::format("{} {}", schema::label(c.spec.problem), schema::to_string(c.spec.mesh));
    add(line, *it->second, c);
    add(out.total, *it->second, c);
    if (c.status == schema::CaseStatus::converged &&
        it->second->status == schema::CaseStatus::converged)
      add(out.total_both_converged, *it->second, c);
  }
  for (auto& [k, l] : lines)
    out.lines.push_back(std::move(l));
  return out;
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

std::string solver_value_cell(const ResultsIndex& index, const schema::RowVerdict* row,
                              schema::MeshLevel mesh) {
  if (row == nullptr)
    return kMissing;
  const std::size_t m = mesh_index(mesh);
  const schema::CaseResult* c = index.case_of(*row, mesh);
  if (!row->values[m]) {
    if (c != nullptr && c->status != schema::CaseStatus::converged)
      return std::string(schema::label(c->status));
    return kMissing;
  }
  std::string out = format_value(*row->values[m]);
  if (row->errors[m])
    out += fmt::format(" ({})", format_percent(*row->errors[m]));
  if (c != nullptr && c->status == schema::CaseStatus::not_converged)
    out += " (not converged)";
  return out;
}

std::vector<std::pair<schema::ProblemId, MarkdownTable>> build_cross_code_appendix(
    const ResultsIndex& index, const StudyReference& study) {
  std::vector<std::pair<schema::ProblemId, MarkdownTable>> out;
  const auto solvers = solvers_in(index);
  for (const schema::ProblemRecord* p : index.problems()) {
    std::vector<std::string> header{"Row", "Exact"};
    for (const auto mesh : kMeshes) {
      for (const auto& s : solvers)
        header.push_back(fmt::format("{} {}", schema::to_string(mesh), solver_display_name(s)));
    }
    header.push_back(fmt::format("{} ANSYS", schema::to_string(kFinestMesh)));
    MarkdownTable t(header);
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<schema::Element>()) {
        for (const auto& o : cross_code_options(index, p->id, q.quantity, element)) {
          std::vector<const schema::RowVerdict*> rows;
          for (const auto& s : solvers)
            rows.push_back(solver_row(index, s, p->id, q.quantity, element, o));
          std::vector<std::string> cells{fmt::format("{} {} {}", schema::to_string(q.quantity),
                                                     schema::to_string(element), o.label()),
                                         exact_cell(index, rows)};
          for (const auto mesh : kMeshes) {
            for (const auto* r : rows)
              cells.push_back(solver_value_cell(index, r, mesh));
          }
          const schema::RowVerdict* any = nullptr;
          for (const auto* r : rows)
            any = any == nullptr ? r : any;
          cells.push_back(any == nullptr ? std::string(kMissing) : ansys_value(study, *any));
          t.add_row(std::move(cells));
        }
      }
    }
    if (t.n_rows() > 0)
      out.emplace_back(p->id, std::move(t));
  }
  return out;
}

std::optional<double> CostLine::time_ratio() const {
  return ours_seconds > 0 ? std::optional(other_seconds / ours_seconds) : std::nullopt;
}

std::optional<double> CostLine::memory_ratio() const {
  return ours_peak_mb > 0 ? std::optional(other_peak_mb / ours_peak_mb) : std::nullopt;
}

std::vector<CrossCodeCost> cross_code_cost(const ResultsIndex& index) {
  const auto ours = ours_by_key(index);
  std::vector<CrossCodeCost> out;
  for (const auto& s : solvers_in(index)) {
    if (s == builtin_solver_label())
      continue;
    CrossCodeCost c = compare(index, s, ours);
    if (c.total.pairs > 0)
      out.push_back(std::move(c));
  }
  return out;
}

MarkdownTable cost_table(const CrossCodeCost& cost) {
  const std::string name = solver_display_name(cost.solver);
  MarkdownTable table({"Cases", "pairs", fmt::format("{} converged", name), "ours (s)",
                       fmt::format("{} (s)", name), "time ratio", "ours peak (MB)",
                       fmt::format("{} peak (MB)", name), "memory ratio"});
  for (const auto& l : cost.lines)
    table.add_row(cells(l));
  table.add_row(cells(cost.total));
  table.add_row(cells(cost.total_both_converged));
  return table;
}

}  // namespace cs::reports

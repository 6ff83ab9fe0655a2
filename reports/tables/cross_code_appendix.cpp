#include "reports/tables/cross_code_appendix.hpp"

#include <fmt/format.h>

#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

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

}  // namespace

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

}  // namespace cs::reports

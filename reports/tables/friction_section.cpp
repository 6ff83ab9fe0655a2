#include "reports/tables/friction_section.hpp"

#include <cmath>

#include <fmt/format.h>

#include "reports/render/template_text.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::Quantity;

constexpr std::size_t kF = mesh_index(kFinestMesh);

bool is_friction_problem(const schema::ProblemRecord& p) {
  return p.definition(Quantity::tau_max) != nullptr;
}

/// "+0.81 % (e, c)" for a row's fine-mesh error and grade; "—" without one.
std::string fine_cell(const ResultsIndex& index, const schema::RowVerdict* row) {
  if (row == nullptr || !row->errors[kF])
    return format_grade_cell(index, row);
  return fmt::format("{} ({})", format_error_resolved(*row->errors[kF]),
                     format_grade_cell(index, row));
}

std::string grades_table(const ResultsIndex& index, const schema::ProblemRecord& p) {
  std::vector<std::string> header{"Element", "Option"};
  for (const auto& q : p.quantities)
    header.push_back(std::string(schema::label(q.quantity)));
  MarkdownTable table(header);
  for (const auto element : schema::values<schema::Element>()) {
    for (const Option& option : all_options()) {
      std::vector<std::string> cells{std::string(schema::to_string(element)), option.label()};
      bool any = false;
      for (const auto& q : p.quantities) {
        const schema::RowVerdict* row = index.row(p.id, q.quantity, element, option);
        any = any || row != nullptr;
        cells.push_back(fine_cell(index, row));
      }
      if (any)
        table.add_row(cells);
    }
  }
  return table.n_rows() == 0 ? std::string() : table.render();
}

/// A difference below the printed resolution (5e-5) as 0, so that it does not print as -0.0000.
double difference_cell(double d) {
  return std::abs(d) < 5e-5 ? 0.0 : d;
}

std::string lmp_plm_table(const ResultsIndex& index, const schema::ProblemRecord& p) {
  MarkdownTable table({"Element", "Contact", "Quantity", "LMP (F)", "PLM (F)", "LMP − PLM"});
  for (const auto element : schema::values<schema::Element>()) {
    for (const auto contact : schema::values<schema::ContactKind>()) {
      for (const auto& q : p.quantities) {
        const auto* lmp = index.row(p.id, q.quantity, element, {Algorithm::LMP, contact});
        const auto* plm = index.row(p.id, q.quantity, element, {Algorithm::PLM, contact});
        if (lmp == nullptr || plm == nullptr || !lmp->values[kF] || !plm->values[kF])
          continue;
        table.add_row({std::string(schema::to_string(element)),
                       std::string(schema::to_string(contact)),
                       std::string(schema::label(q.quantity)),
                       fmt::format("{} ({})", format_value(*lmp->values[kF]),
                                   format_error_resolved(lmp->errors[kF].value_or(NAN))),
                       fmt::format("{} ({})", format_value(*plm->values[kF]),
                                   format_error_resolved(plm->errors[kF].value_or(NAN))),
                       format_value(difference_cell(*lmp->values[kF] - *plm->values[kF]))});
      }
    }
  }
  return table.n_rows() == 0 ? std::string() : table.render();
}

}  // namespace

LmpPlmDifference lmp_plm_difference(const ResultsIndex& index, schema::ProblemId problem) {
  LmpPlmDifference out;
  const schema::ProblemRecord* p = index.problem(problem);
  if (p == nullptr)
    return out;
  for (const auto element : schema::values<schema::Element>()) {
    for (const auto contact : schema::values<schema::ContactKind>()) {
      for (const auto& q : p->quantities) {
        const auto* lmp = index.row(problem, q.quantity, element, {Algorithm::LMP, contact});
        const auto* plm = index.row(problem, q.quantity, element, {Algorithm::PLM, contact});
        if (lmp == nullptr || plm == nullptr || !lmp->errors[kF] || !plm->errors[kF])
          continue;
        const double points = std::abs(*lmp->errors[kF] - *plm->errors[kF]);
        ++out.n_pairs;
        if (points < 0.01)
          ++out.n_equal;
        if (points > out.points)
          out = {points, q.quantity, element, contact, out.n_pairs, out.n_equal};
      }
    }
  }
  return out;
}

std::string friction_section(const ResultsIndex& index) {
  TemplateData problems{TemplateData::type::list};
  for (const schema::ProblemRecord* p : index.problems()) {
    if (!is_friction_problem(*p))
      continue;
    const std::string grades = grades_table(index, *p);
    if (grades.empty())
      continue;
    const LmpPlmDifference diff = lmp_plm_difference(index, p->id);
    TemplateData d;
    d.set("label", std::string(schema::label(p->id)));
    d.set("title", p->title);
    d.set("source", p->exact_source);
    d.set("grades", grades);
    d.set("pairs", text_or_false(lmp_plm_table(index, *p)));
    d.set("all_equal", diff.n_pairs > 0 && diff.n_equal == diff.n_pairs);
    d.set("n_pairs", std::to_string(diff.n_pairs));
    d.set("n_equal", std::to_string(diff.n_equal));
    d.set("points", fmt::format("{:.2f}", diff.points));
    d.set("where", fmt::format("{}, {} {}", schema::label(diff.quantity),
                               schema::to_string(diff.element), schema::to_string(diff.contact)));
    problems.push_back(d);
  }
  if (problems.is_empty_list())
    return {};
  TemplateData d;
  d.set("problems", problems);
  return tidy_markdown(render_template(templates::friction_section, d));
}

}  // namespace cs::reports

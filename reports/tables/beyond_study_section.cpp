#include "reports/tables/beyond_study_section.hpp"

#include <cmath>

#include <fmt/format.h>

#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

std::string order_cell(const std::optional<double>& order) {
  if (!order)
    return kMissing;
  const std::string text = fmt::format("{:.2f}", *order);
  return text[0] == '-' ? "−" + text.substr(1) : text;
}

std::string mesh_cell(const schema::RowVerdict& row, std::size_t m) {
  if (!row.values[m])
    return kMissing;
  std::string cell = format_value(*row.values[m]);
  if (row.errors[m])
    cell += fmt::format(" ({})", format_error_resolved(*row.errors[m]));
  return cell;
}

/// The element size at the contact on each mesh, from the row's cases ("0.25 / 0.125 / —").
std::string sizes_of(const ResultsIndex& index, const schema::RowVerdict& row) {
  std::string out;
  for (const auto mesh : kMeshes) {
    const schema::CaseResult* c = index.case_of(row, mesh);
    out +=
        fmt::format("{}{}", out.empty() ? "" : " / ",
                    c != nullptr && c->element_size_h > 0 ? fmt::format("{:.4g}", c->element_size_h)
                                                          : std::string(kMissing));
  }
  return out;
}

/// A quantity the study did not grade: all of a problem beyond the study, or a quantity
/// added to one of its problems (the contact half-width).
bool beyond_study(const schema::ProblemRecord& p, const schema::QuantityDefinition& q) {
  return !p.singular && (p.study_tables.empty() || q.study_table.empty());
}

std::string problem_tables(const ResultsIndex& index, const schema::ProblemRecord& p) {
  std::string out;
  for (const auto& q : p.quantities) {
    if (!beyond_study(p, q))
      continue;
    MarkdownTable table({"Element", "Option", "C", "M", "F", "Grade", "order C→M", "order M→F"});
    for (const auto element : schema::values<schema::Element>()) {
      for (const auto& option : index.options_present(p.id, q.quantity, element)) {
        const schema::RowVerdict* row = index.row(p.id, q.quantity, element, option);
        table.add_row({std::string(schema::to_string(element)), option.label(), mesh_cell(*row, 0),
                       mesh_cell(*row, 1), mesh_cell(*row, 2), format_grade_cell(index, row),
                       order_cell(row->pair_orders[0]), order_cell(row->pair_orders[1])});
      }
    }
    if (table.n_rows() == 0)
      continue;
    std::optional<double> exact;
    std::string sizes;
    for (const schema::RowVerdict* r : index.baseline_rows()) {
      if (r->spec.problem != p.id || r->quantity != q.quantity)
        continue;
      if (!exact)
        exact = index.exact_of(*r);
      if (sizes.empty())
        sizes = sizes_of(index, *r);
    }
    std::string resolution;
    if (q.quantity == schema::Quantity::contact_half_width) {
      resolution = fmt::format(
          " Its resolution is half an element: the element size at the contact, over the same "
          "length, is {} on C / M / F.",
          sizes);
    } else if (q.quantity == schema::Quantity::p_arc) {
      resolution =
          " Its error is the largest deviation of the nodal contact pressure from the exact one "
          "along the arc, signed.";
    }
    out += fmt::format("### {} — {}: {}\n\n{} = {}, exact {} ({}).{}\n\n{}\n", schema::label(p.id),
                       p.description, schema::label(q.quantity), schema::label(q.quantity),
                       q.definition_md, format_value(exact), p.exact_source, resolution,
                       table.render());
  }
  return out;
}

}  // namespace

std::string format_error_resolved(double percent) {
  if (percent == 0.0 || std::abs(percent) >= 0.01)
    return format_percent(percent);
  const std::string text = fmt::format("{:+.1e} %", percent);
  return text[0] == '-' ? "−" + text.substr(1) : text;
}

std::string beyond_study_section(const ResultsIndex& index) {
  std::string tables;
  for (const schema::ProblemRecord* p : index.problems())
    tables += problem_tables(index, *p);
  if (tables.empty())
    return {};
  return "## Problems and quantities beyond the study\n\n"
         "Problems the study did not run, and quantities it did not grade (the contact "
         "half-width, which the study names as what limits convergence but does not report), "
         "graded by the same rules: Eq. 46 on the finest mesh, "
         "\", c\" when the error shrinks monotonically C → M → F. Each cell: our value (our % "
         "error); errors below 0.01 % are printed to two digits so that an exact result (at "
         "round-off, about 1e-12 %) is told from a small error. The observed order per mesh pair "
         "is log<sub>2</sub> of the ratio of the errors, left out (—) where an error is at "
         "round-off.\n\n" +
         tables;
}

}  // namespace cs::reports

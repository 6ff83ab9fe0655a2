#include "reports/tables/friction_section.hpp"

#include <cmath>

#include <fmt/format.h>

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
    return row == nullptr ? std::string(kMissing) : format_grade_cell(index, row);
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

std::string lmp_plm_words(const ResultsIndex& index, const schema::ProblemRecord& p) {
  const LmpPlmDifference d = lmp_plm_difference(index, p.id);
  if (d.n_pairs == 0)
    return {};
  if (d.n_equal == d.n_pairs) {
    return fmt::format(
        "LMP and PLM agree to within 0.01 percentage points on all {} pairs: the exact state "
        "has the same shear everywhere, so the tangential penalty's elastic slip (shear / kt) is "
        "one rigid shift of the interface and changes no traction.\n\n",
        d.n_pairs);
  }
  return fmt::format(
      "LMP and PLM agree to within 0.01 percentage points on {} of {} pairs; the largest "
      "difference is {:.2f} percentage points ({}, {} {}). PLM holds a sticking point with a "
      "multiplier (no slip increment); LMP holds it with the tangential penalty kt = FKT FKN E/h "
      "w, so it slips elastically by its shear over kt. Where the shear varies along the "
      "contact, that elastic slip varies too, and it redistributes the shear and moves the "
      "stick-slip boundary.\n\n",
      d.n_equal, d.n_pairs, d.points, schema::label(d.quantity), schema::to_string(d.element),
      schema::to_string(d.contact));
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
  std::string body;
  for (const schema::ProblemRecord* p : index.problems()) {
    if (!is_friction_problem(*p))
      continue;
    const std::string grades = grades_table(index, *p);
    if (grades.empty())
      continue;
    body += fmt::format(
        "### {} — {}\n\nFine-mesh error and grade (Eq. 46, \", c\" converging) "
        "of every option, exact values from {}.\n\n{}\n",
        schema::label(p->id), p->title, p->exact_source, grades);
    const std::string pairs = lmp_plm_table(index, *p);
    if (!pairs.empty())
      body += fmt::format("LMP beside PLM, fine mesh:\n\n{}\n{}", pairs, lmp_plm_words(index, *p));
  }
  if (body.empty())
    return {};
  return "## Friction\n\nCoulomb friction (docs/conventions.md, \"Friction\"): the normal load "
         "first, then the tangential one in load steps. MPC is not defined with slip and is not "
         "run.\n\n" +
         body;
}

}  // namespace cs::reports

#include "reports/tables/friction_section.hpp"

#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "grading/convergence.hpp"

#include "reports/facts/row_facts.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::RowVerdict;

constexpr std::size_t kF = mesh_index(kFinestMesh);

/// "+0.81 % (e, c)" for a row's fine-mesh error and grade; "—" without one.
std::string fine_cell(const ResultsIndex& index, const RowVerdict* row) {
  if (row == nullptr || !row->errors[kF])
    return format_grade_cell(index, row);
  return fmt::format("{} ({})", format_error_resolved(*row->errors[kF]),
                     format_marked_grade_cell(index, row));
}

std::string grades_table(const ResultsIndex& index, const schema::ProblemRecord& p) {
  std::vector<std::string> header{"Element", "Option"};
  for (const auto& q : p.quantities)
    header.emplace_back(schema::label(q.quantity));
  MarkdownTable table(header);
  for (const auto element : schema::values<schema::Element>()) {
    for (const Option& option : all_options()) {
      std::vector<std::string> cells{name_of(element), option.label()};
      bool any = false;
      for (const auto& q : p.quantities) {
        const RowVerdict* row = index.row(p.id, q.quantity, element, option);
        any = any || row != nullptr;
        cells.push_back(fine_cell(index, row));
      }
      if (any)
        table.add_row(cells);
    }
  }
  return rendered_if_any(table);
}

/// The LMP and PLM rows of one element, contact type and quantity.
struct LmpPlm {
  schema::Quantity quantity;
  schema::Element element;
  schema::ContactKind contact;
  const RowVerdict *lmp, *plm;
};

/// The pairs of a problem where both rows exist, by element, contact type and quantity.
std::vector<LmpPlm> lmp_plm_pairs(const ResultsIndex& index, const schema::ProblemRecord& p) {
  std::vector<LmpPlm> out;
  for (const auto element : schema::values<schema::Element>()) {
    for (const auto contact : schema::values<schema::ContactKind>()) {
      for (const auto& q : p.quantities) {
        const auto* lmp = index.row(p.id, q.quantity, element, {Algorithm::LMP, contact});
        const auto* plm = index.row(p.id, q.quantity, element, {Algorithm::PLM, contact});
        if (lmp != nullptr && plm != nullptr)
          out.push_back({q.quantity, element, contact, lmp, plm});
      }
    }
  }
  return out;
}

std::string lmp_plm_table(const ResultsIndex& index, const schema::ProblemRecord& p) {
  // A value without an error (an exact value of zero, e.g. a slip length) stands alone.
  const auto cell = [](const RowVerdict* r) {
    return format_value_and_error(r->values[kF], r->errors[kF]);
  };
  MarkdownTable table({"Element", "Contact", "Quantity", "LMP (F)", "PLM (F)", "LMP − PLM"});
  for (const auto& [quantity, element, contact, lmp, plm] : lmp_plm_pairs(index, p)) {
    if (!lmp->values[kF] || !plm->values[kF])
      continue;
    // A difference below the printed resolution as 0, so that it does not print as -0.0000.
    const double difference = *lmp->values[kF] - *plm->values[kF];
    table.add_row({name_of(element), name_of(contact), std::string(schema::label(quantity)),
                   cell(lmp), cell(plm),
                   format_value(std::abs(difference) < 5e-5 ? 0.0 : difference)});
  }
  return rendered_if_any(table);
}

/// The part of one problem; false when it has no row to show.
bool problem_part(const ResultsIndex& index, const schema::ProblemRecord& p, TemplateData& d) {
  const std::string grades = grades_table(index, p);
  const LmpPlmDifference diff = lmp_plm_difference(index, p.id);
  d.set("grades", grades);
  d.set("pairs", text_or_false(lmp_plm_table(index, p)));
  d.set("all_equal", diff.n_pairs > 0 && diff.n_equal == diff.n_pairs);
  d.set("n_pairs", std::to_string(diff.n_pairs));
  d.set("n_equal", std::to_string(diff.n_equal));
  d.set("points", fmt::format("{:.2f}", diff.points));
  d.set("where", join_words(diff.largest_at, "; "));
  d.set("largest_within_noise", diff.points <= diff.largest_noise);
  d.set("largest_noise", fmt::format("{:.2f}", diff.largest_noise));
  d.set("n_beyond_noise", std::to_string(diff.n_beyond_noise));
  return !grades.empty();
}

}  // namespace

LmpPlmDifference lmp_plm_difference(const ResultsIndex& index, schema::ProblemId problem) {
  LmpPlmDifference out;
  if (index.problem(problem) == nullptr)
    return out;
  std::vector<std::pair<LmpPlm, double>> differences;  // of the pairs with both errors on F
  for (const LmpPlm& pair : lmp_plm_pairs(index, *index.problem(problem))) {
    if (!pair.lmp->errors[kF] || !pair.plm->errors[kF])
      continue;
    const double points = std::abs(*pair.lmp->errors[kF] - *pair.plm->errors[kF]);
    const RowFacts a = facts_of_row(index, *pair.lmp), b = facts_of_row(index, *pair.plm);
    const double noise = grading::pair_noise_points(a.m_to_f_change(), b.m_to_f_change(),
                                                    a.read_resolution_on_f, b.read_resolution_on_f);
    differences.emplace_back(pair, points);
    ++out.n_pairs;
    out.n_equal += points < 0.01 ? 1 : 0;
    out.n_beyond_noise += points > noise ? 1 : 0;
    if (points > out.points) {
      out.points = points;
      out.quantity = pair.quantity;
      out.element = pair.element;
      out.contact = pair.contact;
      out.largest_noise = noise;
    }
  }
  for (const auto& [pair, points] : differences) {
    if (std::abs(points - out.points) <= grading::kErrorResolutionPercent)
      out.largest_at.push_back(fmt::format("{}, {} {}", schema::label(pair.quantity),
                                           schema::to_string(pair.element),
                                           schema::to_string(pair.contact)));
  }
  return out;
}

std::string friction_section(const ResultsIndex& index) {
  return per_problem_section(index, schema::Quantity::tau_max, templates::friction_section,
                             std::bind_front(problem_part, std::cref(index)));
}

}  // namespace cs::reports

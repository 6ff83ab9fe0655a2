#include "reports/tables/divergence_table.hpp"

#include <cmath>

#include <fmt/format.h>

#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

std::string verdict(const std::optional<bool>& diverging) {
  if (!diverging)
    return kMissing;
  return *diverging ? "diverges" : "**does not diverge**";
}

std::string difference(const std::optional<double>& a, const std::optional<double>& b) {
  return a && b ? format_value(std::abs(*a - *b)) : std::string(kMissing);
}

}  // namespace

bool satisfies_eq47(double c, double m, double f) {
  return std::abs(c - m) < std::abs(m - f);
}

std::vector<DivergenceRow> build_divergence_rows(const ResultsIndex& index,
                                                 const StudyReference& study) {
  std::vector<DivergenceRow> out;
  for (const schema::ProblemRecord* p : index.problems()) {
    if (!p->singular)
      continue;
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<schema::Element>()) {
        for (const auto& option : index.options_present(p->id, q.quantity, element)) {
          const schema::RowVerdict* row = index.row(p->id, q.quantity, element, option);
          DivergenceRow d{p->id, element, option, row->values, row->diverging, {}, {}};
          for (const auto mesh : kMeshes) {
            const auto match = study.find_value(p->id, q.quantity, element, option.algorithm,
                                                option.contact, mesh);
            if (match.value != nullptr)
              d.study_values[mesh_index(mesh)] = match.value->value;
          }
          if (d.study_values[0] && d.study_values[1] && d.study_values[2]) {
            d.study_diverging =
                satisfies_eq47(*d.study_values[0], *d.study_values[1], *d.study_values[2]);
          }
          out.push_back(d);
        }
      }
    }
  }
  return out;
}

std::string divergence_section(const ResultsIndex& index, const StudyReference& study) {
  const auto rows = build_divergence_rows(index, study);
  if (rows.empty())
    return {};
  const std::string c(schema::to_string(kMeshes[0])), m(schema::to_string(kMeshes[1])),
      f(schema::to_string(kMeshes[2]));
  MarkdownTable table({"Problem", "Element", "Option", c, m, f, fmt::format("|{} − {}|", c, m),
                       fmt::format("|{} − {}|", m, f), "Eq. 47 (ours)",
                       fmt::format("ANSYS {} / {} / {}", c, m, f), "Eq. 47 (ANSYS)"});
  int ours_fail = 0, ours_pass = 0, undecided = 0;
  for (const auto& r : rows) {
    std::string study_cells = kMissing;
    if (r.study_values[0] || r.study_values[1] || r.study_values[2]) {
      study_cells = fmt::format("{} / {} / {}", format_value(r.study_values[0]),
                                format_value(r.study_values[1]), format_value(r.study_values[2]));
    }
    table.add_row({std::string(schema::label(r.problem)), std::string(schema::to_string(r.element)),
                   r.option.label(), format_value(r.values[0]), format_value(r.values[1]),
                   format_value(r.values[2]), difference(r.values[0], r.values[1]),
                   difference(r.values[1], r.values[2]), verdict(r.diverging), study_cells,
                   verdict(r.study_diverging)});
    if (!r.diverging) {
      ++undecided;
    } else if (*r.diverging) {
      ++ours_pass;
    } else {
      ++ours_fail;
    }
  }
  std::string out =
      "## 5. Flat punch: divergence (Eq. 47)\n\n"
      "At the punch edge the exact stress is singular, so a trustworthy element should "
      "*diverge*: Eq. 47 asks |σ̄<sub>C</sub> − σ̄<sub>M</sub>| < |σ̄<sub>M</sub> − "
      "σ̄<sub>F</sub>|. The study found Eq. 47 \"complied with for all contact elements and "
      "options\"; its column here applies the same test to its printed values.\n\n";
  out += table.render() + "\n";
  out += fmt::format(
      "- Ours: {} option set(s) diverge, {} do not, {} without a verdict (— : not "
      "all of C, M, F available).\n",
      ours_pass, ours_fail, undecided);
  std::string mapped;
  for (const auto first : study_columns())
    mapped += (mapped.empty() ? "" : "; ") + study_column_label(first);
  std::string not_in_study;
  for (const auto c : schema::values<schema::ContactKind>()) {
    if (!schema::traits(c).in_study)
      not_in_study += fmt::format("{}{}", not_in_study.empty() ? "" : ", ", schema::to_string(c));
  }
  out += fmt::format(
      "- Option: our algorithm and contact type; the ANSYS column is the study's value for the "
      "mapped option ({}), — where the study printed none{}.\n\n",
      mapped, not_in_study.empty() ? "" : fmt::format(" (e.g. {})", not_in_study));
  return out;
}

}  // namespace cs::reports

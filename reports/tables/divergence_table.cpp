#include "reports/tables/divergence_table.hpp"

#include <cmath>

#include <fmt/format.h>

#include "grading/divergence.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

std::string verdict(const std::optional<bool>& diverging) {
  if (!diverging)
    return kMissing;
  return *diverging ? "diverges" : "**does not diverge**";
}

/// "0.46", "−0.05" (the minus sign as in the other tables).
std::string format_exponent(double alpha) {
  std::string text = fmt::format("{:.2f}", std::abs(alpha) < 0.005 ? 0.0 : alpha);
  return text[0] == '-' ? "−" + text.substr(1) : text;
}

std::string strict_cell(const std::array<std::optional<double>, 3>& values,
                        const std::optional<schema::DivergenceVerdict>& d) {
  if (!d)
    return kMissing;
  if (d->diverges)
    return "diverges";
  return "**does not diverge**: " + strict_failure_reason(values, *d);
}

std::string exponent_cell(const std::optional<schema::DivergenceVerdict>& d) {
  if (!d || !d->exponent)
    return kMissing;
  return format_exponent(*d->exponent);
}

}  // namespace

std::string strict_failure_reason(const std::array<std::optional<double>, 3>& v,
                                  const schema::DivergenceVerdict& d) {
  if (d.diverges)
    return {};
  if (!d.exponent) {
    const bool tensile = (v[0] && *v[0] <= 0) || (v[1] && *v[1] <= 0) || (v[2] && *v[2] <= 0);
    return tensile ? "tensile or changing sign" : "changing sign";
  }
  if (!d.monotone) {
    const bool shrinking = std::abs(*v[2]) < std::abs(*v[1]) && std::abs(*v[1]) < std::abs(*v[0]);
    // -sigma_z/p below 0 on every mesh: the "compressive" edge stress is a tension.
    const bool tensile = *v[0] < 0 && *v[1] < 0 && *v[2] < 0;
    return std::string(tensile ? "tensile, " : "") + (shrinking ? "shrinking" : "not monotone");
  }
  return fmt::format("grows at α {} per halving of h, outside [{}, {}]",
                     format_exponent(*d.exponent), grading::kDivergenceExponentMin,
                     grading::kDivergenceExponentMax);
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
          DivergenceRow d{p->id,           element, option, row->values, row->diverging,
                          row->divergence, {},      {},     {}};
          for (const auto mesh : kMeshes) {
            const auto match = study.find_value(p->id, q.quantity, element, option.algorithm,
                                                option.contact, mesh);
            if (match.value != nullptr)
              d.study_values[mesh_index(mesh)] = match.value->value;
          }
          if (d.study_values[0] && d.study_values[1] && d.study_values[2]) {
            d.study_divergence = grading::divergence_verdict(*d.study_values[0], *d.study_values[1],
                                                             *d.study_values[2]);
            d.study_diverging = d.study_divergence->eq47;
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
  MarkdownTable table({"Problem", "Element", "Option", c, m, f, "Eq. 47 (ours)", "α (ours)",
                       "strict (ours)", fmt::format("ANSYS {} / {} / {}", c, m, f),
                       "Eq. 47 (ANSYS)", "α (ANSYS)", "strict (ANSYS)"});
  int ours_fail = 0, ours_pass = 0, undecided = 0, strict_pass = 0, strict_fail = 0;
  int eq47_only = 0, study_strict_fail = 0;
  for (const auto& r : rows) {
    std::string study_cells = kMissing;
    if (r.study_values[0] || r.study_values[1] || r.study_values[2]) {
      study_cells = fmt::format("{} / {} / {}", format_value(r.study_values[0]),
                                format_value(r.study_values[1]), format_value(r.study_values[2]));
    }
    table.add_row({std::string(schema::label(r.problem)), std::string(schema::to_string(r.element)),
                   r.option.label(), format_value(r.values[0]), format_value(r.values[1]),
                   format_value(r.values[2]), verdict(r.diverging), exponent_cell(r.divergence),
                   strict_cell(r.values, r.divergence), study_cells, verdict(r.study_diverging),
                   exponent_cell(r.study_divergence),
                   strict_cell(r.study_values, r.study_divergence)});
    if (r.divergence) {
      (r.divergence->diverges ? strict_pass : strict_fail)++;
      eq47_only += r.divergence->eq47 && !r.divergence->diverges;
    }
    study_strict_fail += r.study_divergence && !r.study_divergence->diverges;
    if (!r.diverging) {
      ++undecided;
    } else if (*r.diverging) {
      ++ours_pass;
    } else {
      ++ours_fail;
    }
  }
  std::string out = fmt::format(
      "## Flat punch: divergence (Eq. 47 and a strict verdict)\n\n"
      "At the punch edge the exact stress is singular, so a trustworthy element should "
      "*diverge*: the study wants a result \"numerically consistent with stresses increasing "
      "without bound\". Its Eq. 47 asks only |σ̄<sub>C</sub> − σ̄<sub>M</sub>| < "
      "|σ̄<sub>M</sub> − σ̄<sub>F</sub>|, which a tensile, shrinking or oscillating sequence can "
      "pass. The strict verdict asks more: the three values have one sign and grow, "
      "|σ̄<sub>C</sub>| < |σ̄<sub>M</sub>| < |σ̄<sub>F</sub>|, at a rate α (|σ̄| ∝ h<sup>−α</sup>, "
      "the mean of log<sub>2</sub> of the two ratios) in [{}, {}] around the 1/2 of the "
      "square-root singularity at a flat punch's edge (a growth of √2 per halving of h). The "
      "study found Eq. 47 \"complied with for all contact elements and options\"; its columns "
      "apply both verdicts to its printed values.\n\n",
      grading::kDivergenceExponentMin, grading::kDivergenceExponentMax);
  out += table.render() + "\n";
  out += fmt::format(
      "- Ours: by Eq. 47 {} option set(s) diverge, {} do not, {} without a verdict (— : not "
      "all of C, M, F available). By the strict verdict {} diverge and {} do not; {} pass "
      "Eq. 47 without diverging.\n"
      "- ANSYS (the study's values): {} option set(s) fail the strict verdict.\n",
      ours_pass, ours_fail, undecided, strict_pass, strict_fail, eq47_only, study_strict_fail);
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

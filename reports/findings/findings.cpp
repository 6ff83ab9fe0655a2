#include "reports/findings/findings.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "reports/findings/recovery_section.hpp"
#include "reports/tables/divergence_table.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// Fine-mesh errors equal to this many percentage points count as a tie for "best".
constexpr double kTiePercent = 0.005;

using schema::ProblemId;
using schema::RowVerdict;

std::string option_on(const RowVerdict& r) {
  return fmt::format("{} {} on {}", schema::to_string(r.spec.algorithm),
                     schema::to_string(r.spec.contact), schema::to_string(r.spec.element));
}

/// "F<sub>p</sub> sigma_c_star Q4 MPC ss": a row as the findings name it.
std::string row_name(const RowVerdict& r) {
  return fmt::format("{} {} {} {} {}", schema::label(r.spec.problem), schema::to_string(r.quantity),
                     schema::to_string(r.spec.element), schema::to_string(r.spec.algorithm),
                     schema::to_string(r.spec.contact));
}

std::string join_names(const std::vector<std::string>& names, const std::string& last_sep,
                       const std::string& sep = ", ") {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0)
      out += i + 1 == names.size() ? last_sep : sep;
    out += names[i];
  }
  return out;
}

/// The study's best Table 2 cell for a row over both elements: "e, c (AL, PM ss; 4Q)".
std::string study_best(const StudyReference& study, const GradeTableRow& row) {
  const StudyGrade* best = nullptr;
  std::vector<const StudyGrade*> ties;
  for (const auto& g : study.grades()) {
    if (g.problem != row.problem || g.row != row.study_row)
      continue;
    const auto key = std::pair(grade_rank(g.grade), !g.converging);
    if (best == nullptr || key < std::pair(grade_rank(best->grade), !best->converging)) {
      best = &g;
      ties = {&g};
    } else if (key == std::pair(grade_rank(best->grade), !best->converging)) {
      ties.push_back(&g);
    }
  }
  if (best == nullptr)
    return {};
  std::vector<std::string> where;
  for (const auto* g : ties)
    where.push_back(fmt::format("{} {}", g->column_label(), study_name(g->element)));
  return fmt::format("{} ({})", best->cell(), join_names(where, " and "));
}

std::vector<Finding> best_options(const ResultsIndex& index, const StudyReference& study) {
  std::vector<Finding> out;
  const std::size_t fine = mesh_index(kFinestMesh);
  for (const auto& tr : grade_table_rows(index, study)) {
    const auto of_row = [&](const RowVerdict* r) {
      return r->spec.problem == tr.problem && r->quantity == tr.quantity;
    };
    std::vector<const RowVerdict*> graded;
    for (const RowVerdict* r : index.baseline_rows()) {
      if (of_row(r) && r->errors[fine] && r->graded_mesh == kFinestMesh)
        graded.push_back(r);
    }
    if (std::none_of(index.baseline_rows().begin(), index.baseline_rows().end(), of_row))
      continue;
    if (graded.empty()) {
      out.push_back({FindingTopic::best_option,
                     fmt::format("{}: no option set has a fine-mesh (F) result.", tr.label_md)});
      continue;
    }
    std::sort(graded.begin(), graded.end(), [&](const RowVerdict* a, const RowVerdict* b) {
      return std::abs(*a->errors[fine]) < std::abs(*b->errors[fine]);
    });
    const double best_error = std::abs(*graded.front()->errors[fine]);
    std::vector<std::string> best_names;
    for (const RowVerdict* r : graded) {
      if (std::abs(*r->errors[fine]) - best_error <= kTiePercent)
        best_names.push_back(option_on(*r));
    }
    const RowVerdict& best = *graded.front();
    const RowVerdict& worst = *graded.back();
    // A long tie (every option exact on a patch test) is a count, not an enumeration.
    constexpr std::size_t kNamedTies = 3;
    std::string best_md = join_names(best_names, " and ");
    if (best_names.size() > kNamedTies) {
      best_md = fmt::format(
          "{} option sets tied (within {} points), e.g. {}", best_names.size(), kTiePercent,
          join_names({best_names.begin(), best_names.begin() + kNamedTies}, " and "));
    }
    std::string sentence =
        fmt::format("{}: best {} — {} on F ({}{}) of {} option set(s) graded on F", tr.label_md,
                    best_md, format_percent(*best.errors[fine]), schema::to_string(*best.grade),
                    best.converging.value_or(false) ? ", c" : "", graded.size());
    if (graded.size() > 1) {
      sentence +=
          fmt::format("; worst {} ({})", option_on(worst), format_percent(*worst.errors[fine]));
    }
    const std::string theirs = study_best(study, tr);
    if (!theirs.empty())
      sentence += fmt::format(". The study's best ANSYS grade: {}", theirs);
    out.push_back({FindingTopic::best_option, sentence + "."});
  }
  return out;
}

std::vector<Finding> agreement(const ResultsIndex& index, const StudyReference& study) {
  std::vector<Finding> out;
  int compared = 0, same = 0, better = 0, worse = 0;
  for (const auto element : schema::values<schema::Element>()) {
    if (auto t = build_grade_table(index, study, element)) {
      compared += t->cells_compared;
      same += t->cells_same;
      better += t->cells_better;
      worse += t->cells_worse;
    }
  }
  if (compared > 0) {
    out.push_back({FindingTopic::study_agreement,
                   fmt::format("Against the study's Table 2: of {} cells graded by both, our grade "
                               "is the same in {}, better in {} and worse in {}.",
                               compared, same, better, worse)});
  }
  return out;
}

struct Difference {
  const RowVerdict* row;
  double ours, theirs, percent;
};

std::vector<Finding> largest_differences(const ResultsIndex& index, const StudyReference& study) {
  std::vector<Difference> diffs;
  const std::size_t fine = mesh_index(kFinestMesh);
  for (const RowVerdict* r : index.baseline_rows()) {
    if (!r->values[fine])
      continue;
    const auto match = study.find_value(r->spec.problem, r->quantity, r->spec.element,
                                        r->spec.algorithm, r->spec.contact, kFinestMesh);
    if (match.value == nullptr || match.value->value == 0.0)
      continue;
    const double ours = *r->values[fine];
    const double pct = 100.0 * (ours - match.value->value) / std::abs(match.value->value);
    diffs.push_back({r, ours, match.value->value, pct});
  }
  if (diffs.empty())
    return {};
  std::sort(diffs.begin(), diffs.end(), [](const Difference& a, const Difference& b) {
    return std::abs(a.percent) > std::abs(b.percent);
  });
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, diffs.size()); ++i) {
    const auto& d = diffs[i];
    parts.push_back(fmt::format("{} (F: ours {} vs ANSYS {}, {})", row_name(*d.row),
                                format_value(d.ours), format_value(d.theirs),
                                format_percent(d.percent)));
  }
  const auto& closest = diffs.back();
  return {{FindingTopic::largest_difference,
           fmt::format("Of {} fine-mesh values with an ANSYS counterpart, ours and the study's "
                       "differ most on {}; the closest is {} ({}).",
                       diffs.size(), join_names(parts, " and ", "; "), row_name(*closest.row),
                       format_percent(closest.percent))}};
}

std::vector<Finding> divergence(const ResultsIndex& index, const StudyReference& study) {
  const auto rows = build_divergence_rows(index, study);
  if (rows.empty()) {
    std::vector<std::string> punches;
    for (const auto id : study.singular_problems())
      punches.emplace_back(schema::label(id));
    return {{FindingTopic::divergence,
             fmt::format("No flat-punch case ({}) is in this results file, so divergence (Eq. 47) "
                         "is not assessed.",
                         join_names(punches, ", "))}};
  }
  std::vector<std::string> failing, strict_failing;
  int passing = 0, undecided = 0, study_failing = 0, strict_passing = 0, study_strict_failing = 0;
  for (const auto& r : rows) {
    const std::string name = fmt::format("{} {} {}", schema::label(r.problem),
                                         schema::to_string(r.element), r.option.label());
    if (!r.diverging) {
      ++undecided;
    } else if (*r.diverging) {
      ++passing;
    } else {
      failing.push_back(name);
    }
    if (r.divergence && r.divergence->diverges) {
      ++strict_passing;
    } else if (r.divergence) {
      strict_failing.push_back(
          fmt::format("{} ({})", name, strict_failure_reason(r.values, *r.divergence)));
    }
    study_failing += r.study_diverging && !*r.study_diverging;
    study_strict_failing += r.study_divergence && !r.study_divergence->diverges;
  }
  const int decided = passing + static_cast<int>(failing.size());
  std::string sentence = fmt::format(
      "On the flat punch, by the study's Eq. 47 {} of {} option set(s) diverge{}{}. By the strict "
      "verdict (one sign, monotone growth at a rate near the singularity's h<sup>−1/2</sup>) {} "
      "of {} diverge{}{}. On the study's own values Eq. 47 fails for {} and the strict verdict "
      "for {} of the mapped options.",
      passing, decided, failing.empty() ? "" : "; not: ", join_names(failing, ", "), strict_passing,
      strict_passing + static_cast<int>(strict_failing.size()),
      strict_failing.empty() ? "" : "; not: ", join_names(strict_failing, "; ", "; "),
      study_failing, study_strict_failing);
  if (undecided > 0) {
    sentence += fmt::format(" {} more have no verdict (not all of C, M, F).", undecided);
  }
  return {{FindingTopic::divergence, sentence}};
}

/// The mismatched-node patch tests (P′), where the study's node-based options do worst.
bool mismatched_nodes(ProblemId id) {
  return id == ProblemId::Pprime_p || id == ProblemId::Pprime_a;
}

/// "P′": the symbol of a family of problems, their label less its subscript.
std::string family_label(ProblemId id) {
  const std::string_view label = schema::label(id);
  return std::string(label.substr(0, label.find('<')));
}

std::vector<Finding> mortar_on_mismatched(const ResultsIndex& index, const StudyReference& study) {
  using schema::Algorithm;
  using schema::ContactKind;
  std::vector<std::string> parts;
  for (const RowVerdict* r : index.baseline_rows()) {
    if (r->spec.contact != ContactKind::mortar || !mismatched_nodes(r->spec.problem))
      continue;
    std::string ours = format_grade_cell(index, r);
    if (const auto& fine = r->errors[mesh_index(kFinestMesh)])
      ours += fmt::format(", {} on F", format_percent(*fine));
    const schema::QuantityDefinition* d = index.definition(r->spec.problem, r->quantity);
    std::string theirs;
    for (const Algorithm a : {Algorithm::AL, Algorithm::LMP}) {
      const StudyGrade* g = d == nullptr ? nullptr
                                         : study.find_grade(r->spec.problem, d->study_row,
                                                            r->spec.element, a, ContactKind::ss);
      if (g != nullptr)
        theirs += fmt::format("{}{} {}", theirs.empty() ? "" : ", ", g->column_label(), g->cell());
    }
    parts.push_back(fmt::format(
        "{} {} {} {}: {}{}", schema::label(r->spec.problem), schema::to_string(r->spec.element),
        schema::to_string(r->spec.algorithm), schema::to_string(r->spec.contact), ours,
        theirs.empty() ? "" : fmt::format(" (ANSYS: {})", theirs)));
  }
  if (!parts.empty()) {
    return {{FindingTopic::mortar_mismatched,
             fmt::format("On the mismatched-node patch tests, where ANSYS's node-based options "
                         "do worst, {} gives: {}.",
                         schema::to_string(ContactKind::mortar), join_names(parts, "; ", "; "))}};
  }
  const std::string family = family_label(ProblemId::Pprime_p);
  const bool run =
      std::any_of(index.baseline_rows().begin(), index.baseline_rows().end(),
                  [](const RowVerdict* r) { return mismatched_nodes(r->spec.problem); });
  return {
      {FindingTopic::mortar_mismatched,
       run ? fmt::format("The mismatched-node patch tests ({0}) were run without {1}, so "
                         "{1}'s effect there is not assessed.",
                         family, schema::to_string(ContactKind::mortar))
           : fmt::format("No mismatched-node patch test ({}) is in this results file.", family)}};
}

std::vector<Finding> recovery(const ResultsIndex& index) {
  std::vector<std::string> parts;
  for (const auto& c : compare_recoveries(index)) {
    std::string part = fmt::format(
        "{} grades change in {} of {} option sets (better with patch recovery in {}, worse in "
        "{})",
        schema::to_string(c.element), c.better + c.worse, c.compared, c.better, c.worse);
    if (c.differing_with_pressure > 0) {
      part += fmt::format(
          ", and where they change the patch-recovered value is the closer to "
          "the contact pressure in {} of {}",
          c.spr_closer_to_pressure, c.differing_with_pressure);
    }
    parts.push_back(part);
  }
  if (parts.empty())
    return {};
  return {{FindingTopic::recovery,
           fmt::format("Graded with extrapolated nodal stresses, as the study's were, instead of "
                       "patch-recovered ones (section 7): {}.",
                       join_names(parts, "; ", "; "))}};
}

}  // namespace

std::vector<Finding> generate_findings(const ResultsIndex& index, const StudyReference& study) {
  std::vector<Finding> out;
  for (auto part :
       {best_options(index, study), agreement(index, study), largest_differences(index, study),
        divergence(index, study), mortar_on_mismatched(index, study), recovery(index)}) {
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

}  // namespace cs::reports

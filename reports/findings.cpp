#include "reports/findings.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "reports/divergence_table.hpp"
#include "reports/grade_tables.hpp"
#include "reports/markdown_table.hpp"
#include "reports/problem_catalog.hpp"
#include "reports/recovery_section.hpp"

namespace cs::reports {
namespace {

/// Fine-mesh errors equal to this many percentage points count as a tie for "best".
constexpr double kTiePercent = 0.005;

std::string option_on(const RowRecord& r) {
  return fmt::format("{} {} on {}", r.algorithm, r.contact, r.element);
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
  for (const auto* g : ties) {
    std::string column = g->column;
    std::replace(column.begin(), column.end(), '_', ' ');
    if (column.rfind("AL PM", 0) == 0)
      column = "AL, PM" + column.substr(5);
    if (column == "LMP PLM")
      column = "LMP, PLM";
    where.push_back(fmt::format("{} {}", column, g->element));
  }
  return fmt::format("{} ({})", best->cell(), join_names(where, " and "));
}

std::vector<Finding> best_options(const ResultsIndex& index, const StudyReference& study) {
  std::vector<Finding> out;
  for (const auto& tr : grade_table_rows()) {
    std::vector<const RowRecord*> graded;
    for (const RowRecord* r : index.baseline_rows()) {
      if (r->problem == tr.problem && r->quantity == tr.quantity && r->errors[2] &&
          r->graded_mesh.value_or("") == "F")
        graded.push_back(r);
    }
    bool any = std::any_of(
        index.baseline_rows().begin(), index.baseline_rows().end(),
        [&](const RowRecord* r) { return r->problem == tr.problem && r->quantity == tr.quantity; });
    if (!any)
      continue;
    if (graded.empty()) {
      out.push_back({FindingTopic::best_option,
                     fmt::format("{}: no option set has a fine-mesh (F) result.", tr.label_md)});
      continue;
    }
    std::sort(graded.begin(), graded.end(), [](const RowRecord* a, const RowRecord* b) {
      return std::abs(*a->errors[2]) < std::abs(*b->errors[2]);
    });
    const double best_error = std::abs(*graded.front()->errors[2]);
    std::vector<std::string> best_names;
    for (const RowRecord* r : graded) {
      if (std::abs(*r->errors[2]) - best_error <= kTiePercent)
        best_names.push_back(option_on(*r));
    }
    const RowRecord& best = *graded.front();
    const RowRecord& worst = *graded.back();
    std::string sentence =
        fmt::format("{}: best {} — {} on F ({}{}) of {} option set(s) graded on F", tr.label_md,
                    join_names(best_names, " and "), format_percent(*best.errors[2]), *best.grade,
                    best.converging.value_or(false) ? ", c" : "", graded.size());
    if (graded.size() > 1) {
      sentence +=
          fmt::format("; worst {} ({})", option_on(worst), format_percent(*worst.errors[2]));
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
  for (const char* element : {"Q4", "Q8"}) {
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
  const RowRecord* row;
  double ours, theirs, percent;
};

std::vector<Finding> largest_differences(const ResultsIndex& index, const StudyReference& study) {
  std::vector<Difference> diffs;
  for (const RowRecord* r : index.baseline_rows()) {
    if (!r->values[2])
      continue;
    const auto match =
        study.find_value(r->problem, r->quantity, r->element, r->algorithm, r->contact, "F");
    if (match.value == nullptr || match.value->value == 0.0)
      continue;
    const double pct = 100.0 * (*r->values[2] - match.value->value) / std::abs(match.value->value);
    diffs.push_back({r, *r->values[2], match.value->value, pct});
  }
  if (diffs.empty())
    return {};
  std::sort(diffs.begin(), diffs.end(), [](const Difference& a, const Difference& b) {
    return std::abs(a.percent) > std::abs(b.percent);
  });
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, diffs.size()); ++i) {
    const auto& d = diffs[i];
    const ProblemInfo* p = find_problem_info(d.row->problem);
    parts.push_back(fmt::format(
        "{} {} {} {} (F: ours {} vs ANSYS {}, {})", p != nullptr ? p->name_md : d.row->problem,
        d.row->quantity, d.row->element, d.row->algorithm + " " + d.row->contact,
        format_value(d.ours), format_value(d.theirs), format_percent(d.percent)));
  }
  const auto& closest = diffs.back();
  const ProblemInfo* cp = find_problem_info(closest.row->problem);
  return {{FindingTopic::largest_difference,
           fmt::format("Of {} fine-mesh values with an ANSYS counterpart, ours and the study's "
                       "differ most on {}; the closest is {} {} {} {} ({}).",
                       diffs.size(), join_names(parts, " and ", "; "),
                       cp != nullptr ? cp->name_md : closest.row->problem, closest.row->quantity,
                       closest.row->element, closest.row->algorithm + " " + closest.row->contact,
                       format_percent(closest.percent))}};
}

std::vector<Finding> divergence(const ResultsIndex& index, const StudyReference& study) {
  const auto rows = build_divergence_rows(index, study);
  if (rows.empty()) {
    return {{FindingTopic::divergence,
             "No flat-punch case (F<sub>p</sub>, F<sub>a</sub>) is in this results file, so "
             "divergence (Eq. 47) is not assessed."}};
  }
  std::vector<std::string> failing;
  int passing = 0, undecided = 0, study_failing = 0;
  for (const auto& r : rows) {
    if (!r.diverging) {
      ++undecided;
    } else if (*r.diverging) {
      ++passing;
    } else {
      const ProblemInfo* p = find_problem_info(r.problem);
      failing.push_back(fmt::format("{} {} {}", p != nullptr ? p->name_md : r.problem, r.element,
                                    r.option.label()));
    }
    if (r.study_diverging && !*r.study_diverging)
      ++study_failing;
  }
  const std::string study_part =
      study_failing == 0 ? "the study found every ANSYS option diverges"
                         : fmt::format(
                               "on the study's values Eq. 47 fails for {} of the mapped "
                               "options",
                               study_failing);
  std::string sentence;
  if (failing.empty()) {
    sentence = fmt::format(
        "On the flat punch all {} option set(s) with C, M and F diverge "
        "(Eq. 47); {}.",
        passing, study_part);
  } else {
    sentence = fmt::format(
        "On the flat punch {} of {} option set(s) fail to diverge (Eq. 47): {}; "
        "{}.",
        failing.size(), failing.size() + passing, join_names(failing, " and "), study_part);
  }
  if (undecided > 0) {
    sentence += fmt::format(" {} more have no verdict (not all of C, M, F).", undecided);
  }
  return {{FindingTopic::divergence, sentence}};
}

std::vector<Finding> mortar_on_mismatched(const ResultsIndex& index, const StudyReference& study) {
  std::vector<std::string> parts;
  for (const RowRecord* r : index.baseline_rows()) {
    if (r->contact != "mortar" || (r->problem != "Pprime_p" && r->problem != "Pprime_a"))
      continue;
    const ProblemInfo* p = find_problem_info(r->problem);
    std::string ours = format_grade_cell(index, r);
    if (r->errors[2])
      ours += fmt::format(", {} on F", format_percent(*r->errors[2]));
    std::string theirs;
    for (const char* column : {"AL_PM_ss", "LMP_PLM"}) {
      const StudyGrade* g =
          study.find_grade_cell(r->problem, "main", study_element(r->element), column);
      if (g == nullptr)
        continue;
      theirs += fmt::format("{}{} {}", theirs.empty() ? "" : ", ",
                            column == std::string("LMP_PLM") ? "LMP, PLM" : "AL, PM ss", g->cell());
    }
    parts.push_back(fmt::format("{} {} {} mortar: {}{}", p != nullptr ? p->name_md : r->problem,
                                r->element, r->algorithm, ours,
                                theirs.empty() ? "" : fmt::format(" (ANSYS: {})", theirs)));
  }
  if (parts.empty()) {
    const bool pprime =
        std::any_of(index.baseline_rows().begin(), index.baseline_rows().end(),
                    [](const RowRecord* r) { return r->problem.rfind("Pprime", 0) == 0; });
    return {{FindingTopic::mortar_mismatched,
             pprime ? "The mismatched-node patch tests (P′) were run without mortar, so mortar's "
                      "effect there is not assessed."
                    : "No mismatched-node patch test (P′) is in this results file."}};
  }
  return {{FindingTopic::mortar_mismatched,
           fmt::format("On the mismatched-node patch tests, where ANSYS's node-based options do "
                       "worst, mortar gives: {}.",
                       join_names(parts, "; ", "; "))}};
}

std::vector<Finding> recovery(const ResultsIndex& index) {
  std::vector<std::string> parts;
  for (const auto& c : compare_recoveries(index)) {
    std::string part = fmt::format(
        "{} grades change in {} of {} option sets (better with patch recovery in {}, worse in "
        "{})",
        c.element, c.better + c.worse, c.compared, c.better, c.worse);
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

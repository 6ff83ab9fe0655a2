#include "reports/tables/grade_tables.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;

/// A column group of the study's Table 2 and our option sets that belong under it.
struct ColumnGroup {
  std::string name;  ///< "AL, PM (ss)"
  std::vector<Option> candidates;
};

std::vector<ContactKind> contacts_in_study(bool in_study) {
  std::vector<ContactKind> out;
  for (const ContactKind c : schema::values<ContactKind>()) {
    if (schema::traits(c).in_study == in_study)
      out.push_back(c);
  }
  return out;
}

/// The study's columns (split by contact type where its Table 2 splits them), then one group
/// per contact type the study did not have.
std::vector<ColumnGroup> column_groups(const schema::StudyReference& study) {
  std::vector<ColumnGroup> groups;
  for (const Algorithm first : schema::study_columns()) {
    const auto members = schema::study_column_members(first);
    const std::string ours = join_words(names_of(members), ", ");
    const std::string theirs = schema::study_column_label(first);
    const bool split = study.separates_contacts(first);
    const auto contacts = contacts_in_study(true);
    for (const ContactKind c : contacts) {
      if (split || c == contacts.front()) {
        groups.push_back({split            ? fmt::format("{} ({})", ours, schema::to_string(c))
                          : theirs == ours ? ours
                                           : fmt::format("{} ({})", ours, theirs),
                          {}});
      }
      for (const Algorithm a : members)
        groups.back().candidates.push_back({a, c});
    }
  }
  for (const ContactKind c : contacts_in_study(false)) {
    groups.push_back({name_of(c), {}});
    for (const Algorithm a : schema::values<Algorithm>())
      groups.back().candidates.push_back({a, c});
  }
  return groups;
}

/// The pairs whose coincidence the table states: the algorithms of a study column on each
/// contact type, the contact types of a column the study does not separate, then the same
/// algorithms on the types it did not have.
std::vector<std::pair<Option, Option>> stated_pairs(const schema::StudyReference& study) {
  std::vector<std::pair<Option, Option>> out;
  const auto in_study = contacts_in_study(true);
  for (const bool studied : {true, false}) {
    for (const Algorithm first : schema::study_columns()) {
      const auto members = schema::study_column_members(first);
      for (const ContactKind c : contacts_in_study(studied)) {
        for (std::size_t i = 1; i < members.size(); ++i)
          out.push_back({{first, c}, {members[i], c}});
      }
      if (studied && !study.separates_contacts(first) && in_study.size() >= 2)
        out.push_back({{first, in_study[0]}, {first, in_study[1]}});
    }
  }
  return out;
}

PairFacts pair_facts(const Option& a, const Option& b, const OptionComparison& cmp) {
  const auto name = [](auto v) { return schema::to_string(v); };
  const bool same_contact = a.contact == b.contact;
  // Without friction, the Lagrange-multiplier variants of one study column are one method.
  const bool same_method = cmp.coincide() && same_contact && a.algorithm != b.algorithm &&
                           schema::same_study_column(a.algorithm, b.algorithm) &&
                           !schema::traits(a.algorithm).penalty_based;
  return {same_contact
              ? fmt::format("{} and {} ({})", name(a.algorithm), name(b.algorithm), name(a.contact))
              : fmt::format("{} {} and {} {}", name(a.algorithm), name(a.contact),
                            name(b.algorithm), name(b.contact)),
          same_method, cmp};
}

/// ANSYS's fine-mesh grade on our exact value: the study's own where it graded against the same
/// value, else its fine-mesh value re-graded by Eq. 46 against ours (the Steuermann rows, whose
/// printed exact values differ: `regraded`).
struct AnsysGrade {
  schema::Grade grade = schema::Grade::u;
  bool regraded = false;
};
AnsysGrade ansys_grade_on_our_exact(const ResultsIndex& index, const schema::StudyReference& study,
                                    const StudyRowKey& r, schema::Element element,
                                    const Option& option, const schema::RowVerdict* row,
                                    const schema::StudyGrade& printed) {
  if (row == nullptr)
    return AnsysGrade{printed.grade, false};
  const std::optional<double> exact = index.exact_of(*row);
  const auto match = study.find_value(r.problem, *r.quantity, element, option.algorithm,
                                      option.contact, kFinestMesh);
  if (!exact || *exact == 0.0 || match.value == nullptr || !match.value->exact ||
      grading::values_coincide(*match.value->exact, *exact))
    return AnsysGrade{printed.grade, false};
  return AnsysGrade{grading::grade_of_error(grading::error_percent(match.value->value, *exact)),
                    true};
}

/// Counts one cell graded by both; a grade of ours that is not evidence is left out.
void count(AnsysComparison& c, bool evidence, schema::Grade ours, schema::Grade theirs,
           const std::string& where, const std::optional<double>& error) {
  if (!evidence) {
    ++c.not_evidence;
    return;
  }
  ++c.compared;
  // schema::Grade is ordered best first.
  c.same += ours == theirs ? 1 : 0;
  c.better += ours < theirs ? 1 : 0;
  if (ours > theirs) {
    ++c.worse;
    c.worse_cells.push_back(fmt::format(
        "{}: {}", where, error ? format_error_resolved(*error) : std::string(kMissing)));
  }
}

/// Counts a cell's evidence marks (evidence_marks) in `t`.
void count_marks(const ResultsIndex& index, const schema::RowVerdict* row, GradeTableFacts& t) {
  if (row == nullptr || !row->errors[2])
    return;
  const RowFacts f = facts_of_row(index, *row);
  t.not_credible += f.credible ? 0 : 1;
  t.luck += f.luck ? 1 : 0;
}

/// One cell of the table, counted in `t`; a cell compared with ANSYS is graded on extrapolated
/// stresses where the row has a twin, the patch-recovered grade beside it.
std::string table_cell(const ResultsIndex& index, const schema::StudyReference& study,
                       GradeTableFacts& t, const StudyRowKey& r, const OptionClass& cls) {
  const schema::RowVerdict* row = class_row(index, cls, {r.problem, *r.quantity, t.element});
  const Option& first = cls.members.front();
  count_marks(index, row, t);
  const std::string spr = format_marked_grade_cell(index, row);
  // Every column on the extrapolated basis where the row has a twin, mortar's too, though the
  // study has no mortar column to compare.
  const schema::RowVerdict* twin = row ? index.extrapolated_twin(*row) : nullptr;
  std::string text = spr;
  if (twin != nullptr) {
    const bool twin_luck = facts_of_row(index, *twin).luck;
    t.luck += twin_luck ? 1 : 0;
    text = fmt::format("{}{} · spr {}", format_grade_cell(index, twin), twin_luck ? " ‡" : "", spr);
    t.extrapolated = true;
  }
  if (!schema::traits(first.contact).in_study)
    return text;
  const schema::StudyGrade* g =
      study.find_grade(r.problem, r.study_row, t.element, first.algorithm, first.contact);
  text += fmt::format(" │ ANSYS {}", g != nullptr ? g->cell() : std::string(kMissing));
  t.in_study_any = t.in_study_any || g != nullptr;
  if (g == nullptr)
    return text;
  const auto ansys = ansys_grade_on_our_exact(index, study, r, t.element, first, row, *g);
  if (ansys.regraded)
    text += fmt::format(" (phys. {})", schema::to_string(ansys.grade));
  if (row != nullptr && row->grade) {
    const std::string where = r.label_md + " " + cls.label();
    const bool evidence = facts_of_row(index, *row).evidence();
    count(t.patch, evidence, *row->grade, ansys.grade, where, row->errors[2]);
    const schema::RowVerdict* printed = twin && twin->grade ? twin : row;
    count(t.as_printed, evidence && facts_of_row(index, *printed).evidence(), *printed->grade,
          ansys.grade, where, printed->errors[2]);
  }
  return text;
}

TemplateData comparison_data(const AnsysComparison& c) {
  TemplateData d("compared", std::to_string(c.compared));
  d.set("same", std::to_string(c.same));
  d.set("better", std::to_string(c.better));
  d.set("worse", std::to_string(c.worse));
  d.set("worse_cells", joined_or_false(c.worse_cells, "; "));
  d.set("not_evidence", count_or_false(c.not_evidence));
  return d;
}

TemplateData table_data(const GradeTableFacts& t) {
  TemplateData d("study_table", t.study_table);
  d.set("element", name_of(t.element));
  d.set("study_element", std::string(schema::study_name(t.element)));
  d.set("table", t.table.render());
  d.set("twins", t.extrapolated);
  d.set("in_study_any", t.in_study_any);
  d.set("has_compared", t.as_printed.compared + t.as_printed.not_evidence > 0);
  d.set("as_printed", comparison_data(t.as_printed));
  d.set("patch", comparison_data(t.patch));
  d.set("not_credible", std::to_string(t.not_credible));
  d.set("luck", std::to_string(t.luck));
  d.set("pairs", template_list(t.pairs, [](const PairFacts& p) {
          const OptionComparison& c = p.compared;
          TemplateData e("names", p.names);
          e.set("coincide", c.coincide());
          e.set("same_method", p.same_method);
          e.set("compared", std::to_string(c.compared));
          e.set("differing", std::to_string(c.differing));
          e.set("only_one", count_or_false(c.only_one));
          e.set("states_differ", count_or_false(c.states_differ));
          e.set("max_difference", text_or_false(c.max_relative > grading::kCoincidenceRelative
                                                    ? fmt::format("{:.2g} %", c.max_relative * 100)
                                                    : ""));
          e.set("where_max", c.where_max);
          e.set("resolution", fmt::format("{:g} %", grading::kCoincidenceRelative * 100));
          return e;
        }));
  d.set("rows_absent", joined_or_false(t.rows_absent, ", "));
  d.set("groups_absent", joined_or_false(t.groups_absent, "; "));
  return d;
}

}  // namespace

std::vector<StudyRowKey> grade_table_rows(const ResultsIndex& index,
                                          const schema::StudyReference& study) {
  std::vector<StudyRowKey> rows;
  for (const auto& p : index.results().problems) {
    for (const auto& d : p.quantities) {
      if (!d.study_row.empty())
        rows.push_back({p.id, d.quantity, d.study_row, {}});
    }
  }
  for (const auto& [problem, study_row] : study.grade_rows()) {
    if (index.problem(problem) == nullptr)
      rows.push_back({problem, std::nullopt, study_row, {}});
  }
  std::ranges::stable_sort(rows, {}, &StudyRowKey::problem);
  for (auto& r : rows) {
    const auto n = std::ranges::count(rows, r.problem, &StudyRowKey::problem);
    r.label_md = fmt::format("{}{}", schema::label(r.problem),
                             n > 1 ? fmt::format(" ({})", r.study_row) : "");
  }
  return rows;
}

std::string format_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row) {
  if (row == nullptr)
    return kMissing;
  std::string text;
  if (!row->grade) {
    const bool failed = std::ranges::any_of(
        kMeshes, [&](schema::MeshLevel m) { return index.state(*row, m) == MeshState::failed; });
    text = failed ? name_of(schema::CaseStatus::failed) : kMissing;
  } else {
    text = schema::to_string(*row->grade);
    if (row->converging.value_or(false))
      text += ", c";
    if (row->graded_mesh && *row->graded_mesh != kFinestMesh)
      text += fmt::format(" ({})", schema::to_string(*row->graded_mesh));
    if (!ResultsIndex::complete(*row))
      text += "*";
  }
  return index.any_not_converged(*row) ? text + "!" : text;
}

std::string evidence_marks(const RowFacts& f) {
  return std::string(f.credible ? "" : " ✗") + (f.luck ? " ‡" : "");
}

std::string open_read_grades(const RowFacts& f) {
  if (!f.read_leaves_grade_open())
    return {};
  const double e = *f.errors[2], r = f.read_resolution_on_f;
  const schema::Grade best = grading::best_reading_grade(e, r);
  const schema::Grade worst = grading::worst_reading_grade(e, r);
  return best == worst ? std::string()
                       : fmt::format(" ({}–{})", schema::to_string(best), schema::to_string(worst));
}

std::string format_marked_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row) {
  const std::string text = format_grade_cell(index, row);
  if (row == nullptr || !row->errors[2])
    return text;
  const RowFacts f = facts_of_row(index, *row);
  return text + open_read_grades(f) + evidence_marks(f);
}

std::string evidence_marks_legend() {
  return render_template(templates::evidence_marks, TemplateData(true));
}

std::optional<GradeTableFacts> build_grade_table(const ResultsIndex& index,
                                                 const schema::StudyReference& study,
                                                 schema::Element element) {
  std::vector<Slot> slots;
  std::vector<StudyRowKey> present;
  GradeTableFacts facts;
  facts.element = element;
  for (const auto& r : grade_table_rows(index, study)) {
    if (r.quantity && index.has(r.problem, *r.quantity, element)) {
      slots.push_back({r.problem, *r.quantity, element});
      present.push_back(r);
    } else {
      facts.rows_absent.push_back(r.label_md);
    }
  }
  if (slots.empty())
    return std::nullopt;
  facts.study_table = study.grade_table(element).empty() ? "2" : study.grade_table(element);

  std::vector<std::string> header{"Problem"};
  std::vector<OptionClass> classes;
  for (const auto& group : column_groups(study)) {
    const auto group_classes = coincidence_classes(index, group.candidates, slots);
    if (group_classes.empty())
      facts.groups_absent.push_back(group.name);
    for (const auto& cls : group_classes) {
      classes.push_back(cls);
      header.push_back(cls.label());
    }
  }
  facts.table = MarkdownTable(header);
  for (const auto& r : present) {
    std::vector<std::string> row{r.label_md};
    for (const auto& cls : classes)
      row.push_back(table_cell(index, study, facts, r, cls));
    facts.table.add_row(std::move(row));
  }
  for (const auto& [a, b] : stated_pairs(study)) {
    const auto cmp = compare_options(index, a, b, slots);
    if (cmp.compared > 0)
      facts.pairs.push_back(pair_facts(a, b, cmp));
  }
  return facts;
}

std::string grade_tables_section(const ResultsIndex& index, const schema::StudyReference& study) {
  std::vector<GradeTableFacts> tables;
  for (const auto element : schema::values<schema::Element>()) {
    if (auto t = build_grade_table(index, study, element))
      tables.push_back(std::move(*t));
  }
  if (tables.empty())
    return {};
  TemplateData d("tables", template_list(tables, table_data));
  std::vector<std::string> renamed;
  for (const Algorithm a : schema::values<Algorithm>()) {
    if (schema::study_name(a) != schema::to_string(a))
      renamed.push_back(
          fmt::format("{} is the study's {}", schema::to_string(a), schema::study_name(a)));
  }
  for (const ContactKind c : contacts_in_study(false))
    renamed.push_back(fmt::format("{} was not in the study", schema::to_string(c)));
  d.set("study_names", fmt::format("{}", fmt::join(renamed, "; ")));
  return tidy_markdown(render_template(templates::grade_tables, d));
}

}  // namespace cs::reports

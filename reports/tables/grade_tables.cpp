#include "reports/tables/grade_tables.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;

/// A column group of the study's Table 2 and our option sets that belong under it.
struct ColumnGroup {
  std::string name;  ///< for notes: "AL, PM (ss)"
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

std::string names_of(const std::vector<Algorithm>& algorithms) {
  std::string out;
  for (const Algorithm a : algorithms)
    out += fmt::format("{}{}", out.empty() ? "" : ", ", schema::to_string(a));
  return out;
}

/// The study's columns (split by contact type where its Table 2 splits them), then one group
/// per contact type the study did not have: "AL, PM (ss)", "AL, PM (ns)", "LMP, PLM",
/// "MPC (IMC)", "mortar".
std::vector<ColumnGroup> column_groups(const StudyReference& study) {
  std::vector<ColumnGroup> groups;
  for (const Algorithm first : study_columns()) {
    const auto members = study_column_members(first);
    const std::string ours = names_of(members);
    if (study.separates_contacts(first)) {
      for (const ContactKind c : contacts_in_study(true)) {
        ColumnGroup g{fmt::format("{} ({})", ours, schema::to_string(c)), {}};
        for (const Algorithm a : members)
          g.candidates.push_back({a, c});
        groups.push_back(std::move(g));
      }
      continue;
    }
    const std::string theirs = study_column_label(first);
    ColumnGroup g{theirs == ours ? ours : fmt::format("{} ({})", ours, theirs), {}};
    for (const ContactKind c : contacts_in_study(true)) {
      for (const Algorithm a : members)
        g.candidates.push_back({a, c});
    }
    groups.push_back(std::move(g));
  }
  for (const ContactKind c : contacts_in_study(false)) {
    ColumnGroup g{std::string(schema::to_string(c)), {}};
    for (const Algorithm a : schema::values<Algorithm>())
      g.candidates.push_back({a, c});
    groups.push_back(std::move(g));
  }
  return groups;
}

/// The pairs whose coincidence the notes state (the study's groupings, and ours): the
/// algorithms of a study column on each contact type, the contact types of a study column
/// that the study does not separate, then the same algorithms on the types it did not have.
std::vector<std::pair<Option, Option>> stated_pairs(const StudyReference& study) {
  std::vector<std::pair<Option, Option>> out;
  const auto in_study = contacts_in_study(true);
  for (const Algorithm first : study_columns()) {
    const auto members = study_column_members(first);
    for (const ContactKind c : in_study) {
      for (std::size_t i = 1; i < members.size(); ++i)
        out.push_back({{first, c}, {members[i], c}});
    }
    if (!study.separates_contacts(first) && in_study.size() >= 2)
      out.push_back({{first, in_study[0]}, {first, in_study[1]}});
  }
  for (const ContactKind c : contacts_in_study(false)) {
    for (const Algorithm first : study_columns()) {
      const auto members = study_column_members(first);
      for (std::size_t i = 1; i < members.size(); ++i)
        out.push_back({{first, c}, {members[i], c}});
    }
  }
  return out;
}

std::string pair_statement(const Option& a, const Option& b, const OptionComparison& cmp) {
  const bool same_contact = a.contact == b.contact;
  const auto name = [](auto v) { return schema::to_string(v); };
  const std::string names =
      same_contact
          ? fmt::format("{} and {} ({})", name(a.algorithm), name(b.algorithm), name(a.contact))
          : fmt::format("{} {} and {} {}", name(a.algorithm), name(a.contact), name(b.algorithm),
                        name(b.contact));
  const std::string unpaired =
      cmp.only_one > 0 ? fmt::format(" ({} row(s) have only one of them)", cmp.only_one) : "";
  if (cmp.coincide()) {
    // Without friction, the Lagrange-multiplier variants of one study column are one method.
    const bool same_method = same_contact && a.algorithm != b.algorithm &&
                             same_study_column(a.algorithm, b.algorithm) &&
                             !schema::traits(a.algorithm).penalty_based;
    return fmt::format(
        "{}{} coincide on all {} rows where both ran (values within {} % on every "
        "mesh){}: one column.",
        names, same_method ? ", the same method without friction," : "", cmp.compared,
        kCoincidenceRelative * 100, unpaired);
  }
  std::string how;
  if (cmp.max_relative > kCoincidenceRelative) {
    how = fmt::format("largest value difference {:.2g} % at {}", cmp.max_relative * 100,
                      cmp.where_max);
  }
  if (cmp.states_differ > 0) {
    how += fmt::format(
        "{}their cases ended differently (missing, failed, not converged) on {} "
        "row(s)",
        how.empty() ? "" : "; ", cmp.states_differ);
  }
  return fmt::format("{} differ on {} of {} rows ({}){}: separate columns.", names, cmp.differing,
                     cmp.compared, how, unpaired);
}

/// "MPC is the study's IMC; mortar was not in the study.": the study's other names and what
/// it did not have.
std::string study_names_note() {
  std::string out;
  for (const Algorithm a : schema::values<Algorithm>()) {
    if (study_name(a) != schema::to_string(a)) {
      out += fmt::format("{}{} is the study's {}", out.empty() ? "" : "; ", schema::to_string(a),
                         study_name(a));
    }
  }
  for (const ContactKind c : contacts_in_study(false))
    out += fmt::format("{}{} was not in the study", out.empty() ? "" : "; ", schema::to_string(c));
  return out.empty() ? out : out + ".";
}

std::string joined(const std::vector<std::string>& names, const char* separator) {
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : separator) + n;
  return out;
}

/// Where the study graded against a printed exact value other than ours (the Steuermann rows:
/// its 9.9773 against the physical 10.1956), ANSYS's fine-mesh value re-graded by Eq. 46
/// against the physical value, e.g. " (phys. g)"; empty elsewhere.
std::string ansys_physical_regrade(const ResultsIndex& index, const StudyReference& study,
                                   const GradeTableRow& r, schema::Element element,
                                   const Option& option, const schema::RowVerdict* row) {
  if (row == nullptr || !r.quantity)
    return {};
  const auto exact = index.exact_of(*row);
  const auto match = study.find_value(r.problem, *r.quantity, element, option.algorithm,
                                      option.contact, kFinestMesh);
  if (!exact || *exact == 0.0 || match.value == nullptr || !match.value->exact)
    return {};
  if (std::abs(*match.value->exact - *exact) <= 1e-4 * std::abs(*exact))
    return {};  // the study's exact value is ours
  const double error = grading::error_percent(match.value->value, *exact);
  return fmt::format(" (phys. {})", schema::to_string(grading::grade_of_error(error)));
}

/// Our cell of one option class, beside the study's grade; counts the comparison.
std::string table_cell(const ResultsIndex& index, const StudyReference& study,
                       const GradeTableRow& r, const OptionClass& cls, GradeTable& table,
                       bool& in_study_any) {
  const schema::RowVerdict* row = class_row(index, cls, {r.problem, *r.quantity, table.element});
  std::string text = format_grade_cell(index, row);
  const Option& first = cls.members.front();
  if (!schema::traits(first.contact).in_study)
    return text;
  const StudyGrade* g =
      study.find_grade(r.problem, r.study_row, table.element, first.algorithm, first.contact);
  text += fmt::format(" │ ANSYS {}", g != nullptr ? g->cell() : std::string(kMissing));
  text += ansys_physical_regrade(index, study, r, table.element, first, row);
  in_study_any = in_study_any || g != nullptr;
  if (g != nullptr && row != nullptr && row->grade) {
    ++table.cells_compared;
    const int ours = grade_rank(*row->grade), theirs = grade_rank(g->grade);
    table.cells_same += ours == theirs ? 1 : 0;
    table.cells_better += ours < theirs ? 1 : 0;
    table.cells_worse += ours > theirs ? 1 : 0;
  }
  return text;
}

void add_notes(const ResultsIndex& index, const StudyReference& study,
               const std::vector<Slot>& slots, const std::string& study_table, bool in_study_any,
               const std::vector<std::string>& rows_absent,
               const std::vector<std::string>& groups_absent, GradeTable& table) {
  auto& notes = table.notes;
  notes.push_back(fmt::format(
      "Each cell: our grade (Eq. 46 on the fine mesh F), \", c\" when converging, then │ the "
      "study's ANSYS grade from its Table {}{}. {}",
      study_table, in_study_any ? "" : " (none of these cells is in the study)",
      study_names_note()));
  notes.push_back(
      "Markers: — not in this results file; (M) graded on the medium mesh because F is missing "
      "or failed; * not all of C, M, F present, so no convergence verdict; ! contact iterations "
      "did not converge on some mesh (its value is the last iterate).");
  notes.push_back(
      "Exact values: our grades use the physically consistent exact value of each row. Where "
      "the study printed another (the Steuermann rows: Eq. 32 without the plane-strain factor "
      "1 − ν²; the appendix tables give both values and the shift), its ANSYS grade is shown as "
      "the study gave it, followed by \"(phys. …)\": ANSYS's fine-mesh value re-graded by "
      "Eq. 46 against the physical value, so that both columns rest on the same reference.");
  if (table.cells_compared > 0) {
    notes.push_back(fmt::format(
        "Against the study: of {} cells graded by both, ours is the same in {}, better in {} and "
        "worse in {}.",
        table.cells_compared, table.cells_same, table.cells_better, table.cells_worse));
  }
  for (const auto& [a, b] : stated_pairs(study)) {
    const auto cmp = compare_options(index, a, b, slots);
    if (cmp.compared > 0)
      notes.push_back(pair_statement(a, b, cmp));
  }
  if (!rows_absent.empty()) {
    notes.push_back(fmt::format("Rows of the study's Table {} not in this results file: {}.",
                                study_table, joined(rows_absent, ", ")));
  }
  if (!groups_absent.empty()) {
    notes.push_back(
        fmt::format("Columns with no case in this results file: {}.", joined(groups_absent, "; ")));
  }
}

}  // namespace

std::vector<GradeTableRow> grade_table_rows(const ResultsIndex& index,
                                            const StudyReference& study) {
  std::vector<GradeTableRow> rows;
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
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.problem < b.problem; });
  std::map<schema::ProblemId, int> rows_per_problem;
  for (const auto& r : rows)
    ++rows_per_problem[r.problem];
  for (auto& r : rows) {
    r.label_md = std::string(schema::label(r.problem));
    if (rows_per_problem[r.problem] > 1)
      r.label_md += fmt::format(" ({})", r.study_row);
  }
  return rows;
}

std::string format_grade_cell(const ResultsIndex& index, const schema::RowVerdict* row) {
  if (row == nullptr)
    return kMissing;
  std::string text;
  if (!row->grade) {
    const bool failed = std::any_of(kMeshes.begin(), kMeshes.end(), [&](schema::MeshLevel m) {
      return index.state(*row, m) == MeshState::failed;
    });
    text = failed ? std::string(schema::to_string(schema::CaseStatus::failed)) : kMissing;
  } else {
    text = schema::to_string(*row->grade);
    if (row->converging.value_or(false))
      text += ", c";
    if (row->graded_mesh && *row->graded_mesh != kFinestMesh)
      text += fmt::format(" ({})", schema::to_string(*row->graded_mesh));
    if (!ResultsIndex::complete(*row))
      text += "*";
  }
  if (index.any_not_converged(*row))
    text += "!";
  return text;
}

std::optional<std::string> GradeTable::cell(const std::string& row_label,
                                            const std::string& column) const {
  for (const auto& r : rows) {
    if (r.empty() || r[0] != row_label)
      continue;
    for (std::size_t j = 0; j < columns.size() && j < r.size(); ++j) {
      if (columns[j] == column)
        return r[j];
    }
  }
  return std::nullopt;
}

std::string GradeTable::markdown() const {
  MarkdownTable table(columns);
  for (const auto& r : rows)
    table.add_row(r);
  std::string out = fmt::format("### {}\n\n{}\n", title, table.render());
  for (const auto& n : notes)
    out += fmt::format("- {}\n", n);
  return out + "\n";
}

std::optional<GradeTable> build_grade_table(const ResultsIndex& index, const StudyReference& study,
                                            schema::Element element) {
  std::vector<Slot> slots;
  std::vector<GradeTableRow> rows_present;
  std::vector<std::string> rows_absent;
  for (const auto& r : grade_table_rows(index, study)) {
    if (r.quantity && index.has(r.problem, *r.quantity, element)) {
      slots.push_back({r.problem, *r.quantity, element});
      rows_present.push_back(r);
    } else {
      rows_absent.push_back(r.label_md);
    }
  }
  if (slots.empty())
    return std::nullopt;

  GradeTable table;
  table.element = element;
  std::string study_table = study.grade_table(element);
  if (study_table.empty())
    study_table = "2";
  table.title = fmt::format(
      "Table {}′ — accuracy and convergence of {} elements (the study's Table "
      "{}, {})",
      study_table, schema::to_string(element), study_table, study_name(element));
  table.columns.push_back("Problem");

  std::vector<OptionClass> classes;
  std::vector<std::string> groups_absent;
  for (const auto& group : column_groups(study)) {
    const auto group_classes = coincidence_classes(index, group.candidates, slots);
    if (group_classes.empty())
      groups_absent.push_back(group.name);
    for (const auto& cls : group_classes) {
      classes.push_back(cls);
      table.columns.push_back(cls.label());
    }
  }

  bool in_study_any = false;
  for (const auto& r : rows_present) {
    std::vector<std::string> cells{r.label_md};
    for (const auto& cls : classes)
      cells.push_back(table_cell(index, study, r, cls, table, in_study_any));
    table.rows.push_back(std::move(cells));
  }
  add_notes(index, study, slots, study_table, in_study_any, rows_absent, groups_absent, table);
  return table;
}

std::string grade_tables_section(const ResultsIndex& index, const StudyReference& study) {
  std::string out;
  for (const auto element : schema::values<schema::Element>()) {
    if (auto table = build_grade_table(index, study, element))
      out += table->markdown();
  }
  if (out.empty())
    return out;
  return "## Accuracy and convergence: Tables 2a and 2b\n\n" + out;
}

}  // namespace cs::reports

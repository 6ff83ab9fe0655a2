#include "reports/grade_tables.hpp"

#include <fmt/format.h>

#include "reports/markdown_table.hpp"
#include "reports/option_classes.hpp"
#include "reports/problem_catalog.hpp"

namespace cs::reports {
namespace {

/// A column group of the study's Table 2 and our option sets that belong under it.
struct ColumnGroup {
  std::string name;  ///< for notes: "AL, PM (ss)"
  std::vector<Option> candidates;
};

std::vector<ColumnGroup> column_groups() {
  return {
      {"AL, PM (ss)", {{"AL", "ss"}, {"PM", "ss"}}},
      {"AL, PM (ns)", {{"AL", "ns"}, {"PM", "ns"}}},
      {"LMP, PLM", {{"LMP", "ss"}, {"PLM", "ss"}, {"LMP", "ns"}, {"PLM", "ns"}}},
      {"MPC (IMC)", {{"MPC", "ss"}, {"MPC", "ns"}}},
      {"mortar",
       {{"AL", "mortar"},
        {"PM", "mortar"},
        {"LMP", "mortar"},
        {"PLM", "mortar"},
        {"MPC", "mortar"}}},
  };
}

/// The pairs whose coincidence the notes state (the study's groupings, and ours).
std::vector<std::pair<Option, Option>> stated_pairs() {
  return {{{"AL", "ss"}, {"PM", "ss"}},         {{"AL", "ns"}, {"PM", "ns"}},
          {{"LMP", "ss"}, {"PLM", "ss"}},       {{"LMP", "ns"}, {"PLM", "ns"}},
          {{"LMP", "ss"}, {"LMP", "ns"}},       {{"MPC", "ss"}, {"MPC", "ns"}},
          {{"AL", "mortar"}, {"PM", "mortar"}}, {{"LMP", "mortar"}, {"PLM", "mortar"}}};
}

std::string pair_statement(const Option& a, const Option& b, const OptionComparison& cmp) {
  const bool same_contact = a.contact == b.contact;
  const std::string names =
      same_contact ? fmt::format("{} and {} ({})", a.algorithm, b.algorithm, a.contact)
                   : fmt::format("{} {} and {} {}", a.algorithm, a.contact, b.algorithm, b.contact);
  const std::string unpaired =
      cmp.only_one > 0 ? fmt::format(" ({} row(s) have only one of them)", cmp.only_one) : "";
  if (cmp.coincide()) {
    const bool lagrange = same_contact && a.algorithm == "LMP" && b.algorithm == "PLM";
    return fmt::format(
        "{}{} coincide on all {} rows where both ran (values within {} % on every "
        "mesh){}: one column.",
        names, lagrange ? ", the same method without friction," : "", cmp.compared,
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

}  // namespace

int grade_rank(const std::string& grade) {
  if (grade == "e")
    return 0;
  if (grade == "g")
    return 1;
  if (grade == "s")
    return 2;
  if (grade == "u")
    return 3;
  return 4;
}

std::string format_grade_cell(const ResultsIndex& index, const RowRecord* row) {
  if (row == nullptr)
    return kMissing;
  std::string text;
  if (!row->grade) {
    bool failed = false;
    for (std::size_t m = 0; m < kMeshLevels.size(); ++m)
      failed = failed || index.state(*row, m) == MeshState::failed;
    text = failed ? "failed" : kMissing;
  } else {
    text = *row->grade;
    if (row->converging.value_or(false))
      text += ", c";
    if (row->graded_mesh && *row->graded_mesh != "F")
      text += fmt::format(" ({})", *row->graded_mesh);
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
                                            const std::string& element) {
  std::vector<Slot> slots;
  std::vector<const GradeTableRow*> rows_present;
  std::vector<std::string> rows_absent;
  for (const auto& r : grade_table_rows()) {
    if (index.has(r.problem, r.quantity, element)) {
      slots.push_back({r.problem, r.quantity, element});
      rows_present.push_back(&r);
    } else {
      rows_absent.push_back(r.label_md);
    }
  }
  if (slots.empty())
    return std::nullopt;

  GradeTable table;
  table.element = element;
  const std::string study_table = element == "Q4" ? "2a" : "2b";
  table.title = fmt::format(
      "Table {}′ — accuracy and convergence of {} elements (the study's Table "
      "{}, {})",
      study_table, element, study_table, study_element(element));
  table.columns.push_back("Problem");

  std::vector<OptionClass> classes;
  std::vector<std::string> groups_absent;
  for (const auto& group : column_groups()) {
    const auto group_classes = coincidence_classes(index, group.candidates, slots);
    if (group_classes.empty())
      groups_absent.push_back(group.name);
    for (const auto& cls : group_classes) {
      classes.push_back(cls);
      table.columns.push_back(cls.label());
    }
  }

  bool in_study_any = false;
  for (const auto* r : rows_present) {
    std::vector<std::string> cells{r->label_md};
    const Slot slot{r->problem, r->quantity, element};
    for (const auto& cls : classes) {
      const RowRecord* row = class_row(index, cls, slot);
      std::string text = format_grade_cell(index, row);
      const Option& first = cls.members.front();
      if (first.contact != "mortar") {
        const StudyGrade* g =
            study.find_grade(r->problem, r->study_row, element, first.algorithm, first.contact);
        text += fmt::format(" │ ANSYS {}", g != nullptr ? g->cell() : std::string(kMissing));
        in_study_any = in_study_any || g != nullptr;
        if (g != nullptr && row != nullptr && row->grade) {
          ++table.cells_compared;
          const int ours = grade_rank(*row->grade), theirs = grade_rank(g->grade);
          if (ours == theirs)
            ++table.cells_same;
          if (ours < theirs)
            ++table.cells_better;
          if (ours > theirs)
            ++table.cells_worse;
        }
      }
      cells.push_back(text);
    }
    table.rows.push_back(std::move(cells));
  }

  auto& notes = table.notes;
  notes.push_back(fmt::format(
      "Each cell: our grade (Eq. 46 on the fine mesh F), \", c\" when converging, then │ the "
      "study's ANSYS grade from its Table {}{}. MPC is the study's IMC; mortar was not in the "
      "study.",
      study_table, in_study_any ? "" : " (none of these cells is in the study)"));
  notes.push_back(
      "Markers: — not in this results file; (M) graded on the medium mesh because F is missing "
      "or failed; * not all of C, M, F present, so no convergence verdict; ! contact iterations "
      "did not converge on some mesh (its value is the last iterate).");
  if (table.cells_compared > 0) {
    notes.push_back(fmt::format(
        "Against the study: of {} cells graded by both, ours is the same in {}, better in {} and "
        "worse in {}.",
        table.cells_compared, table.cells_same, table.cells_better, table.cells_worse));
  }
  for (const auto& [a, b] : stated_pairs()) {
    const auto cmp = compare_options(index, a, b, slots);
    if (cmp.compared > 0)
      notes.push_back(pair_statement(a, b, cmp));
  }
  if (!rows_absent.empty()) {
    std::string names;
    for (const auto& n : rows_absent)
      names += (names.empty() ? "" : ", ") + n;
    notes.push_back(fmt::format("Rows of the study's Table {} not in this results file: {}.",
                                study_table, names));
  }
  if (!groups_absent.empty()) {
    std::string names;
    for (const auto& n : groups_absent)
      names += (names.empty() ? "" : "; ") + n;
    notes.push_back(fmt::format("Columns with no case in this results file: {}.", names));
  }
  return table;
}

std::string grade_tables_section(const ResultsIndex& index, const StudyReference& study) {
  std::string out;
  for (const char* element : {"Q4", "Q8"}) {
    if (auto table = build_grade_table(index, study, element))
      out += table->markdown();
  }
  if (out.empty())
    return out;
  return "## 2. Accuracy and convergence: Tables 2a and 2b\n\n" + out;
}

}  // namespace cs::reports

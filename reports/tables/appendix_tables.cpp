#include "reports/tables/appendix_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::RowVerdict;

const std::string kFailed(schema::to_string(schema::CaseStatus::failed));

std::string algorithms_label(const OptionClass& cls) {
  std::string out;
  for (const auto& m : cls.members)
    out += fmt::format("{}{}", out.empty() ? "" : " = ", schema::to_string(m.algorithm));
  return out;
}

/// "a, b and c".
std::string join_and(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return out;
}

/// Our value on one mesh: "1.2741 (+0.07 %)", "2.1318" (singular), "failed", "—"; + "!" when
/// the contact iterations did not converge.
std::string our_value_cell(const ResultsIndex& index, const RowVerdict* row,
                           schema::MeshLevel mesh) {
  if (row == nullptr)
    return kMissing;
  const MeshState state = index.state(*row, mesh);
  if (state == MeshState::failed)
    return kFailed;
  const std::size_t m = mesh_index(mesh);
  if (!row->values[m])
    return kMissing;
  std::string text = format_value(*row->values[m]);
  if (row->errors[m])
    text += fmt::format(" ({})", format_percent(*row->errors[m]));
  if (state == MeshState::not_converged)
    text += "!";
  return text;
}

std::string element_size_cell(const ResultsIndex& index, const std::vector<const RowVerdict*>& rows,
                              schema::MeshLevel mesh) {
  for (const RowVerdict* r : rows) {
    const schema::CaseResult* c = index.case_of(*r, mesh);
    if (c != nullptr && finite(c->element_size_h))
      return fmt::format("{:.5g}", c->element_size_h);
  }
  return kMissing;
}

/// A column of a table: one of our option classes, or the study's column of an algorithm.
struct Column {
  std::optional<OptionClass> ours;
  Algorithm study_column = Algorithm::AL;  ///< for ANSYS columns: its first algorithm
};

/// Per study column: our classes of option sets on this contact type, then the study's
/// column when it printed any value for it.
std::vector<Column> table_layout(const ResultsIndex& index, const StudyReference& study,
                                 AppendixTable& t, std::vector<const RowVerdict*>& our_rows) {
  const Slot slot{t.problem, t.quantity, t.element};
  std::vector<Column> layout;
  for (const Algorithm first : study_columns()) {
    std::vector<Option> candidates;
    for (const auto& o : all_options()) {
      if (o.contact == t.contact && same_study_column(o.algorithm, first))
        candidates.push_back(o);
    }
    for (const auto& cls : coincidence_classes(index, candidates, {slot})) {
      layout.push_back({cls, first});
      t.columns.push_back(algorithms_label(cls));
      if (const RowVerdict* r = class_row(index, cls, slot))
        our_rows.push_back(r);
    }
    const bool study_has = std::any_of(kMeshes.begin(), kMeshes.end(), [&](schema::MeshLevel m) {
      return study.find_value(t.problem, t.quantity, t.element, first, t.contact, m).value !=
             nullptr;
    });
    if (study_has) {
      layout.push_back({std::nullopt, first});
      t.columns.push_back("ANSYS " + study_column_label(first));
    }
  }
  return layout;
}

/// What the cells of a table hold, for its title and notes.
struct CellsSeen {
  std::set<std::string> tables;  ///< the study's tables the ANSYS values come from
  bool via_note = false, missing = false, failed = false, not_converged = false;
};

void fill_rows(const ResultsIndex& index, const StudyReference& study,
               const std::vector<Column>& layout, const std::vector<const RowVerdict*>& our_rows,
               AppendixTable& t, CellsSeen& seen) {
  const Slot slot{t.problem, t.quantity, t.element};
  for (const auto mesh : kMeshes) {
    std::vector<std::string> cells{std::string(schema::to_string(mesh)),
                                   element_size_cell(index, our_rows, mesh)};
    for (const auto& col : layout) {
      if (col.ours) {
        std::string text = our_value_cell(index, class_row(index, *col.ours, slot), mesh);
        seen.missing = seen.missing || text == kMissing;
        seen.failed = seen.failed || text == kFailed;
        seen.not_converged = seen.not_converged || (!text.empty() && text.back() == '!');
        cells.push_back(text);
        continue;
      }
      const StudyMatch match =
          study.find_value(t.problem, t.quantity, t.element, col.study_column, t.contact, mesh);
      if (match.value == nullptr) {
        cells.push_back(kMissing);
        continue;
      }
      seen.tables.insert(match.value->table);
      seen.via_note = seen.via_note || match.via_ss_note;
      cells.push_back(match.value->printed + (match.via_ss_note ? " ˢ" : ""));
    }
    t.rows.push_back(std::move(cells));
  }
}

void add_title_and_notes(const std::vector<Column>& layout, const CellsSeen& seen,
                         AppendixTable& t) {
  std::string table_list;
  for (const auto& name : seen.tables)
    table_list += (table_list.empty() ? "" : ", ") + name;
  t.title =
      fmt::format("{} from {} {} elements{}", schema::label(t.quantity),
                  schema::traits(t.contact).words, schema::to_string(t.element),
                  table_list.empty() ? std::string(" (not in the study)")
                                     : fmt::format(" (ANSYS: the study's Table {})", table_list));
  if (!t.rows.empty() && std::any_of(layout.begin(), layout.end(), [](const Column& c) {
        return c.ours && c.ours->members.size() > 1;
      })) {
    t.notes.push_back("A = B: those algorithms give the same values here (within 0.01 %).");
  }
  if (seen.via_note) {
    t.notes.push_back(fmt::format(
        "ˢ the study's {} value: its {} table prints no {} column (\"{} have the same results "
        "as for {} elements\").",
        schema::traits(ContactKind::ss).words, schema::traits(ContactKind::ns).words,
        study_column_label(Algorithm::LMP), study_column_label(Algorithm::LMP),
        schema::traits(ContactKind::ss).words));
  }
  if (seen.missing)
    t.notes.push_back("— not in this results file.");
  if (seen.failed)
    t.notes.push_back(fmt::format("{0}: the case has a status `{0}` (see results.csv).", kFailed));
  if (seen.not_converged) {
    t.notes.push_back("! contact iterations did not converge; the value is the last iterate.");
  }
}

AppendixTable build_one(const ResultsIndex& index, const StudyReference& study,
                        schema::ProblemId problem, schema::Quantity quantity,
                        schema::Element element, ContactKind contact) {
  AppendixTable t{problem, quantity, element, contact, {}, {"Mesh", "h"}, {}, {}};
  std::vector<const RowVerdict*> our_rows;
  const std::vector<Column> layout = table_layout(index, study, t, our_rows);
  CellsSeen seen;
  fill_rows(index, study, layout, our_rows, t, seen);
  add_title_and_notes(layout, seen, t);
  return t;
}

/// The section's opening paragraph: the layout and the mapping of our options onto the
/// study's columns.
std::string appendix_intro(const StudyReference& study) {
  std::string mapping;
  std::vector<std::string> either, in_study;
  for (const Algorithm first : study_columns()) {
    std::string ours;
    for (const Algorithm a : study_column_members(first))
      ours += fmt::format("{}{}", ours.empty() ? "" : "/", schema::to_string(a));
    mapping += mapping.empty() ? fmt::format("Our {} map to the study's \"{}\"", ours,
                                             study_column_label(first))
                               : fmt::format(", {} to \"{}\"", ours, study_column_label(first));
    if (!study.separates_contacts(first))
      either.push_back(study_column_label(first));
  }
  for (const ContactKind c : schema::values<ContactKind>()) {
    if (schema::traits(c).in_study)
      in_study.emplace_back(schema::to_string(c));
  }
  return fmt::format(
      "## Appendix tables: our values beside the study's ANSYS values\n\n"
      "Layout of the study's Tables 3–14: per problem, quantity, element and contact type, rows "
      "C, M, F (h = element size at the contact over a, or b for S); per algorithm our value "
      "(our % error) and the study's ANSYS value as printed. {}; the study's {} columns marked "
      "\"either {} or {}\" are shown beside both our {} tables.\n\n",
      mapping, join_and(either), schema::traits(ContactKind::ns).words,
      schema::traits(ContactKind::ss).words, join_and(in_study));
}

}  // namespace

std::optional<std::string> AppendixTable::cell(schema::MeshLevel mesh,
                                               const std::string& column) const {
  const std::string mesh_name(schema::to_string(mesh));
  for (const auto& r : rows) {
    if (r.empty() || r[0] != mesh_name)
      continue;
    for (std::size_t j = 0; j < columns.size() && j < r.size(); ++j) {
      if (columns[j] == column)
        return r[j];
    }
  }
  return std::nullopt;
}

std::string AppendixTable::markdown() const {
  MarkdownTable table(columns);
  for (const auto& r : rows)
    table.add_row(r);
  std::string out = fmt::format("**{}**\n\n{}\n", title, table.render());
  for (const auto& n : notes)
    out += fmt::format("- {}\n", n);
  return out + (notes.empty() ? "" : "\n");
}

std::vector<AppendixTable> build_appendix_tables(const ResultsIndex& index,
                                                 const StudyReference& study) {
  std::vector<AppendixTable> out;
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      if (q.study_table.empty())
        continue;  // not in the study's appendix: see beyond_study_section.hpp
      for (const auto element : schema::values<schema::Element>()) {
        const auto present = index.options_present(p->id, q.quantity, element);
        for (const auto contact : schema::values<ContactKind>()) {
          const bool any = std::any_of(present.begin(), present.end(),
                                       [&](const Option& o) { return o.contact == contact; });
          if (any)
            out.push_back(build_one(index, study, p->id, q.quantity, element, contact));
        }
      }
    }
  }
  return out;
}

namespace {

/// The study's printed exact value as a number (empty text or not a number: none).
std::optional<double> parse_printed(const std::string& printed) {
  if (printed.empty())
    return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(printed.c_str(), &end);
  if (end == printed.c_str() || *end != '\0' || !std::isfinite(v))
    return std::nullopt;
  return v;
}

}  // namespace

std::string exact_value_line(const ResultsIndex& index, const StudyReference& study,
                             schema::ProblemId problem, schema::Quantity quantity) {
  const schema::ProblemRecord* p = index.problem(problem);
  const schema::QuantityDefinition* q = index.definition(problem, quantity);
  std::optional<double> exact, study_exact;
  for (const RowVerdict* r : index.baseline_rows()) {
    if (r->spec.problem != problem || r->quantity != quantity)
      continue;
    if (!exact)
      exact = index.exact_of(*r);
    if (!study_exact)
      study_exact = index.study_exact_of(*r);
  }
  const std::string printed = study.printed_exact(problem, quantity);
  const std::string head = q != nullptr
                               ? fmt::format("{} = {}", schema::label(quantity), q->definition_md)
                               : std::string(schema::to_string(quantity));
  if (p != nullptr && p->singular) {
    return fmt::format(
        "{} → ∞ (analytical value from the study's {}): not graded for accuracy; "
        "see the divergence table (Eq. 47).",
        head, p->exact_source);
  }
  std::string line = fmt::format("{} = {} (exact, from the study's {}; our errors are against it)",
                                 head, exact ? format_value(*exact) : std::string(kMissing),
                                 p != nullptr ? p->exact_source : "");
  const std::optional<double> printed_value = parse_printed(printed);
  if (printed_value && exact && *exact != 0.0) {
    line += fmt::format(
        "; the study printed {} and graded its ANSYS values against that, {} from ours, so "
        "its grades rest on a different exact value (compare its columns with its own)",
        printed, format_percent(grading::error_percent(*printed_value, *exact)));
    if (study_exact && format_value(*study_exact) != printed) {
      line += fmt::format(
          "; the study's convention elsewhere (docs/conventions.md) gives {} here, so its "
          "printed value follows from neither convention",
          format_value(*study_exact));
    }
  } else if (study_exact) {
    line += fmt::format("; under the study's convention (docs/conventions.md) it is {}",
                        format_value(*study_exact));
  }
  return line + ".";
}

std::string appendix_section(const ResultsIndex& index, const StudyReference& study) {
  const auto tables = build_appendix_tables(index, study);
  if (tables.empty())
    return {};
  std::string out = appendix_intro(study);
  std::optional<std::pair<schema::ProblemId, schema::Quantity>> current;
  for (const auto& t : tables) {
    if (!current || *current != std::pair(t.problem, t.quantity)) {
      current = std::pair(t.problem, t.quantity);
      const schema::ProblemRecord* p = index.problem(t.problem);
      const schema::QuantityDefinition* q = index.definition(t.problem, t.quantity);
      out += fmt::format("### {} — {}: {} (the study's Table {})\n\n{}\n\n",
                         schema::label(t.problem), p != nullptr ? p->description : "",
                         schema::description(t.quantity), q != nullptr ? q->study_table : "?",
                         exact_value_line(index, study, t.problem, t.quantity));
    }
    out += t.markdown();
  }
  return out;
}

}  // namespace cs::reports

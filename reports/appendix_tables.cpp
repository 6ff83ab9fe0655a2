#include "reports/appendix_tables.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "reports/markdown_table.hpp"
#include "reports/option_classes.hpp"
#include "reports/problem_catalog.hpp"

namespace cs::reports {
namespace {

const char* contact_words(const std::string& contact) {
  if (contact == "ss")
    return "surface-to-surface";
  if (contact == "ns")
    return "node-to-surface";
  return "mortar";
}

/// One of our algorithms that maps onto a study algorithm key (for the study lookup).
std::string representative_algorithm(const std::string& study_key) {
  if (study_key == "AL_PM")
    return "AL";
  if (study_key == "LMP_PLM")
    return "LMP";
  return "MPC";
}

std::string algorithms_label(const OptionClass& cls) {
  std::string out;
  for (const auto& m : cls.members)
    out += (out.empty() ? "" : " = ") + m.algorithm;
  return out;
}

/// Our value on one mesh: "1.2741 (+0.07 %)", "2.1318" (singular), "failed", "—"; + "!" when
/// the contact iterations did not converge.
std::string our_value_cell(const ResultsIndex& index, const RowRecord* row, std::size_t mesh) {
  if (row == nullptr)
    return kMissing;
  const MeshState state = index.state(*row, mesh);
  if (state == MeshState::failed)
    return "failed";
  if (!row->values[mesh])
    return kMissing;
  std::string text = format_value(*row->values[mesh]);
  if (row->errors[mesh])
    text += fmt::format(" ({})", format_percent(*row->errors[mesh]));
  if (state == MeshState::not_converged)
    text += "!";
  return text;
}

std::string element_size_cell(const ResultsIndex& index, const std::vector<const RowRecord*>& rows,
                              std::size_t mesh) {
  for (const RowRecord* r : rows) {
    const CaseRecord* c = index.case_of(*r, mesh);
    if (c != nullptr && c->element_size_h)
      return fmt::format("{:.5g}", *c->element_size_h);
  }
  return kMissing;
}

AppendixTable build_one(const ResultsIndex& index, const StudyReference& study,
                        const std::string& problem, const std::string& quantity,
                        const std::string& element, const std::string& contact) {
  AppendixTable t{problem, quantity, element, contact, {}, {"Mesh", "h"}, {}, {}};
  const Slot slot{problem, quantity, element};
  const QuantityInfo* qi = find_quantity_info(problem, quantity);

  struct Column {
    std::optional<OptionClass> ours;  ///< our class, or nullopt for an ANSYS column
    std::string study_algorithm;      ///< for ANSYS columns
  };
  std::vector<Column> layout;
  std::vector<const RowRecord*> all_rows;
  for (const char* group : {"AL_PM", "LMP_PLM", "IMC"}) {
    std::vector<Option> candidates;
    for (const auto& o : all_options()) {
      if (o.contact == contact && study_algorithm(o.algorithm) == group)
        candidates.push_back(o);
    }
    const auto classes = coincidence_classes(index, candidates, {slot});
    for (const auto& cls : classes) {
      layout.push_back({cls, {}});
      t.columns.push_back(algorithms_label(cls));
      if (const RowRecord* r = class_row(index, cls, slot))
        all_rows.push_back(r);
    }
    bool study_has = false;
    for (const char* mesh : kMeshLevels) {
      study_has = study_has || study.find_value(problem, quantity, element,
                                                representative_algorithm(group), contact, mesh)
                                       .value != nullptr;
    }
    if (study_has) {
      layout.push_back({std::nullopt, group});
      t.columns.push_back("ANSYS " + study_algorithm_label(group));
    }
  }

  std::set<std::string> tables;
  bool via_note = false, missing = false, failed = false, not_converged = false;
  for (std::size_t m = 0; m < kMeshLevels.size(); ++m) {
    std::vector<std::string> cells{kMeshLevels[m], element_size_cell(index, all_rows, m)};
    for (const auto& col : layout) {
      if (col.ours) {
        const RowRecord* r = class_row(index, *col.ours, slot);
        std::string text = our_value_cell(index, r, m);
        missing = missing || text == kMissing;
        failed = failed || text == "failed";
        not_converged = not_converged || (!text.empty() && text.back() == '!');
        cells.push_back(text);
        continue;
      }
      const StudyMatch match =
          study.find_value(problem, quantity, element,
                           representative_algorithm(col.study_algorithm), contact, kMeshLevels[m]);
      if (match.value == nullptr) {
        cells.push_back(kMissing);
        continue;
      }
      tables.insert(match.value->table);
      via_note = via_note || match.via_ss_note;
      cells.push_back(match.value->printed + (match.via_ss_note ? " ˢ" : ""));
    }
    t.rows.push_back(std::move(cells));
  }

  std::string table_list;
  for (const auto& name : tables)
    table_list += (table_list.empty() ? "" : ", ") + name;
  t.title =
      fmt::format("{} from {} {} elements{}", qi != nullptr ? qi->symbol_md : quantity,
                  contact_words(contact), element,
                  table_list.empty() ? std::string(" (not in the study)")
                                     : fmt::format(" (ANSYS: the study's Table {})", table_list));
  if (!t.rows.empty() && std::any_of(layout.begin(), layout.end(), [](const Column& c) {
        return c.ours && c.ours->members.size() > 1;
      })) {
    t.notes.push_back("A = B: those algorithms give the same values here (within 0.01 %).");
  }
  if (via_note) {
    t.notes.push_back(
        "ˢ the study's surface-to-surface value: its node-to-surface table prints no "
        "LMP, PLM column (\"LMP, PLM have the same results as for "
        "surface-to-surface elements\").");
  }
  if (missing)
    t.notes.push_back("— not in this results file.");
  if (failed)
    t.notes.push_back("failed: the case has a status `failed` (see results.csv).");
  if (not_converged) {
    t.notes.push_back("! contact iterations did not converge; the value is the last iterate.");
  }
  return t;
}

}  // namespace

std::optional<std::string> AppendixTable::cell(const std::string& mesh,
                                               const std::string& column) const {
  for (const auto& r : rows) {
    if (r.empty() || r[0] != mesh)
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
  for (const auto& p : all_problem_infos()) {
    for (const auto& q : p.quantities) {
      for (const char* element : {"Q4", "Q8"}) {
        const auto present = index.options_present(p.id, q.name, element);
        for (const char* contact : {"ss", "ns", "mortar"}) {
          const bool any = std::any_of(present.begin(), present.end(),
                                       [&](const Option& o) { return o.contact == contact; });
          if (any)
            out.push_back(build_one(index, study, p.id, q.name, element, contact));
        }
      }
    }
  }
  return out;
}

std::string exact_value_line(const ResultsIndex& index, const StudyReference& study,
                             const std::string& problem, const std::string& quantity) {
  const ProblemInfo* p = find_problem_info(problem);
  const QuantityInfo* q = find_quantity_info(problem, quantity);
  std::optional<double> exact, study_exact;
  for (const RowRecord* r : index.baseline_rows()) {
    if (r->problem != problem || r->quantity != quantity)
      continue;
    if (!exact)
      exact = index.exact_of(*r);
    if (!study_exact)
      study_exact = index.study_exact_of(*r);
  }
  const std::string printed = study.printed_exact(problem, quantity);
  const std::string head =
      q != nullptr ? fmt::format("{} = {}", q->symbol_md, q->definition_md) : quantity;
  if (p != nullptr && p->singular) {
    return fmt::format(
        "{} → ∞ (analytical value from the study's {}): not graded for accuracy; "
        "see the divergence table (Eq. 47).",
        head, p->exact_source);
  }
  std::string line = fmt::format("{} = {} (exact, from the study's {}; our errors are against it)",
                                 head, exact ? format_value(*exact) : std::string(kMissing),
                                 p != nullptr ? p->exact_source : "");
  if (study_exact) {
    line += fmt::format(
        "; the study printed {} and graded its ANSYS values against that, so compare its "
        "columns with its own exact value",
        format_value(*study_exact));
  } else if (!printed.empty()) {
    line += fmt::format("; the study printed {}", printed);
  }
  return line + ".";
}

std::string appendix_section(const ResultsIndex& index, const StudyReference& study) {
  const auto tables = build_appendix_tables(index, study);
  if (tables.empty())
    return {};
  std::string out =
      "## 3. Appendix tables: our values beside the study's ANSYS values\n\n"
      "Layout of the study's Tables 3–14: per problem, quantity, element and contact type, rows "
      "C, M, F (h = element size at the contact over a, or b for S); per algorithm our value "
      "(our % error) and the study's ANSYS value as printed. Our AL/PM map to the study's "
      "\"AL, PM\", LMP/PLM to \"LMP, PLM\", MPC to \"IMC\"; the study's LMP, PLM and IMC columns "
      "marked \"either node-to-surface or surface-to-surface\" are shown beside both our ss and ns "
      "tables.\n\n";
  std::string current;
  for (const auto& t : tables) {
    const std::string key = t.problem + "/" + t.quantity;
    if (key != current) {
      current = key;
      const ProblemInfo* p = find_problem_info(t.problem);
      const QuantityInfo* q = find_quantity_info(t.problem, t.quantity);
      out += fmt::format("### {} — {}: {} (the study's Table {})\n\n{}\n\n",
                         p != nullptr ? p->name_md : t.problem, p != nullptr ? p->description : "",
                         q != nullptr ? q->what : t.quantity, q != nullptr ? q->study_table : "?",
                         exact_value_line(index, study, t.problem, t.quantity));
    }
    out += t.markdown();
  }
  return out;
}

}  // namespace cs::reports

#include "reports/tables/appendix_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/accuracy.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::RowVerdict;

const std::string kFailed(schema::to_string(schema::CaseStatus::failed));

/// Our value on one mesh: "1.2741 (+0.07 %)", "2.1318" (singular), "failed", "—"; + "!" when
/// the contact iterations did not converge; on F, the row's evidence marks (✗ an interface check
/// failed, ‡ the luck of one mesh).
std::string our_value_cell(const ResultsIndex& index, const RowVerdict* row,
                           schema::MeshLevel mesh) {
  if (row == nullptr)
    return kMissing;
  const MeshState state = index.state(*row, mesh);
  const std::size_t m = mesh_index(mesh);
  if (state == MeshState::failed)
    return kFailed;
  std::string text = format_value_and_error(row->values[m], row->errors[m]);
  if (mesh == schema::MeshLevel::F && row->errors[m])
    text += evidence_marks(facts_of_row(index, *row));
  return state == MeshState::not_converged && row->values[m] ? text + "!" : text;
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

/// A column: one of our option classes (`ours`), or the study's column of `study_column`.
struct ColumnSource {
  std::optional<OptionClass> ours;
  Algorithm study_column = Algorithm::AL;
};

AppendixTableFacts build_one(const ResultsIndex& index, const schema::StudyReference& study,
                             const AppendixTableFacts& key) {
  AppendixTableFacts t = key;
  const Slot slot{t.problem, t.quantity, t.element};
  std::vector<ColumnSource> sources;
  std::vector<std::string> header{"Mesh", "h"};
  std::vector<const RowVerdict*> our_rows;
  for (const Algorithm first : schema::study_columns()) {
    std::vector<Option> candidates;
    for (const auto& o : all_options()) {
      if (o.contact == t.contact && schema::same_study_column(o.algorithm, first))
        candidates.push_back(o);
    }
    for (const auto& cls : coincidence_classes(index, candidates, {slot})) {
      sources.push_back({cls, first});
      std::vector<std::string_view> names;
      for (const auto& m : cls.members)
        names.push_back(schema::to_string(m.algorithm));
      header.push_back(fmt::format("{}", fmt::join(names, " = ")));
      t.merged = t.merged || cls.members.size() > 1;
      if (const RowVerdict* r = class_row(index, cls, slot))
        our_rows.push_back(r);
    }
    const bool study_has = std::ranges::any_of(kMeshes, [&](schema::MeshLevel m) {
      return study.find_value(t.problem, t.quantity, t.element, first, t.contact, m).value;
    });
    if (study_has) {
      sources.push_back({std::nullopt, first});
      header.push_back("ANSYS " + schema::study_column_label(first));
    }
  }
  t.table = MarkdownTable(header);
  for (const auto mesh : kMeshes) {
    std::vector<std::string> cells{name_of(mesh), element_size_cell(index, our_rows, mesh)};
    for (const auto& col : sources) {
      if (col.ours) {
        // On ANSYS's basis where the case ran: its extrapolated nodal stresses.
        const RowVerdict* row = class_row(index, *col.ours, slot);
        const RowVerdict* twin = row ? index.extrapolated_twin(*row) : nullptr;
        t.extrapolated = t.extrapolated || twin != nullptr;
        const std::string text = our_value_cell(index, twin ? twin : row, mesh);
        t.missing = t.missing || text == kMissing;
        t.failed = t.failed || text == kFailed;
        t.not_converged = t.not_converged || text.back() == '!';
        cells.push_back(text);
        continue;
      }
      const schema::StudyMatch match =
          study.find_value(t.problem, t.quantity, t.element, col.study_column, t.contact, mesh);
      if (match.value != nullptr) {
        t.study_tables.insert(match.value->table);
        t.via_note = t.via_note || match.via_ss_note;
      }
      cells.push_back(match.value == nullptr
                          ? std::string(kMissing)
                          : match.value->printed + (match.via_ss_note ? " ˢ" : ""));
    }
    t.table.add_row(std::move(cells));
  }
  return t;
}

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

TemplateData table_data(const AppendixTableFacts& t) {
  TemplateData d("quantity", std::string(schema::label(t.quantity)));
  d.set("contact", std::string(schema::traits(t.contact).words));
  d.set("element", name_of(t.element));
  d.set("study_tables", joined_or_false(t.study_tables, ", "));
  d.set("table", t.table.render());
  d.set("merged", t.merged);
  d.set("via_note", t.via_note);
  d.set("missing", t.missing);
  d.set("failed", t.failed);
  d.set("not_converged", t.not_converged);
  d.set("extrapolated", t.extrapolated);
  return d;
}

/// The facts above a group of tables (one problem and quantity of the results).
TemplateData group_data(const ResultsIndex& index, const schema::StudyReference& study,
                        const AppendixTableFacts& t) {
  const schema::ProblemRecord& p = *index.problem(t.problem);
  const schema::QuantityDefinition& q = *index.definition(t.problem, t.quantity);
  const ExactValueFacts e = exact_value_facts(index, study, t.problem, t.quantity);
  TemplateData d("problem", std::string(schema::label(t.problem)));
  d.set("description", p.description);
  d.set("quantity_words", std::string(schema::description(t.quantity)));
  d.set("study_table", q.study_table);
  d.set("head", fmt::format("{} = {}", schema::label(t.quantity), q.definition_md));
  d.set("source", p.exact_source);
  d.set("singular", e.singular);
  d.set("exact", e.exact ? format_value(*e.exact) : std::string(kMissing));
  d.set("printed", text_or_false(e.printed ? study.printed_exact(t.problem, t.quantity) : ""));
  d.set("shift", e.printed_shift ? format_error_resolved(*e.printed_shift) : "");
  d.set("convention", text_or_false(e.convention ? format_value(*e.convention) : ""));
  d.set("convention_differs",
        e.printed && e.convention &&
            format_value(*e.convention) != study.printed_exact(t.problem, t.quantity));
  return d;
}

}  // namespace

std::vector<AppendixTableFacts> build_appendix_tables(const ResultsIndex& index,
                                                      const schema::StudyReference& study) {
  std::vector<AppendixTableFacts> out;
  for (const Slot& s : slots_of(index)) {
    if (index.definition(s.problem, s.quantity)->study_table.empty())
      continue;  // not in the study's appendix
    const auto present = index.options_present(s.problem, s.quantity, s.element);
    for (const auto contact : schema::values<ContactKind>()) {
      if (std::ranges::any_of(present, [&](const Option& o) { return o.contact == contact; }))
        out.push_back(build_one(index, study, {s.problem, s.quantity, s.element, contact}));
    }
  }
  return out;
}

ExactValueFacts exact_value_facts(const ResultsIndex& index, const schema::StudyReference& study,
                                  schema::ProblemId problem, schema::Quantity quantity) {
  ExactValueFacts out;
  const schema::ProblemRecord* p = index.problem(problem);
  out.singular = p != nullptr && p->singular;
  for (const RowVerdict* r : index.baseline_rows()) {
    if (r->spec.problem != problem || r->quantity != quantity)
      continue;
    out.exact = out.exact ? out.exact : index.exact_of(*r);
    out.convention = out.convention ? out.convention : index.study_exact_of(*r);
  }
  // The study's printed exact value, where it differs from ours at the study's resolution.
  out.printed = parse_printed(study.printed_exact(problem, quantity));
  if (out.printed && out.exact && *out.exact != 0.0 &&
      !grading::values_coincide(*out.printed, *out.exact))
    out.printed_shift = grading::error_percent(*out.printed, *out.exact);
  else
    out.printed.reset();
  return out;
}

std::string appendix_section(const ResultsIndex& index, const schema::StudyReference& study) {
  const auto tables = build_appendix_tables(index, study);
  if (tables.empty())
    return {};
  TemplateData groups{TemplateData::type::list};
  for (auto t = tables.begin(); t != tables.end();) {
    TemplateData group = group_data(index, study, *t);
    TemplateData list{TemplateData::type::list};
    for (const auto first = t;
         t != tables.end() && t->problem == first->problem && t->quantity == first->quantity; ++t)
      list.push_back(table_data(*t));
    group.set("tables", list);
    groups.push_back(group);
  }
  TemplateData d("groups", groups);
  d.set("marks_legend", evidence_marks_legend());
  return tidy_markdown(render_template(templates::appendix_tables, d));
}

}  // namespace cs::reports

#include "reports/pages/problem_page.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::Element;

std::string trend_word(const RowFacts& f) {
  if (!f.trend)
    return kMissing;
  return std::string(schema::label(f.trend->trend));
}

/// "yes", "F not converged" or "no: force balance 19.2 tensile pressure 167" (with "; luck of
/// one mesh" where `luck`): a row's facts, nonsingular or singular.
template <typename Facts>
std::string credible_cell(const Facts& f, bool luck) {
  if (!f.fine_converged)
    return "F not converged";
  if (f.credible)
    return luck ? "yes; luck of one mesh" : "yes";
  std::string out = "no:";
  for (const auto& failure : f.failures)
    out += fmt::format(" {}{}", failure.check,
                       failure.measure ? fmt::format(" {:.3g}", *failure.measure) : "");
  return out + (luck ? "; luck of one mesh" : "");
}

/// The option label of a row, "AL, PM ss" when its twin coincides (the twin is then skipped).
std::string option_label(const RowFacts& f, const std::vector<const RowFacts*>& rows, bool& skip) {
  skip = false;
  std::optional<schema::Algorithm> twin_algorithm;  // the other of its family: AL-PM, LMP-PLM
  for (const auto a : schema::values<schema::Algorithm>()) {
    if (a != f.option.algorithm && family_of(a) == family_of(f.option.algorithm))
      twin_algorithm = a;
  }
  for (const RowFacts* t : rows) {
    if (!twin_algorithm || t->option.algorithm != *twin_algorithm ||
        t->option.contact != f.option.contact || t->element != f.element ||
        t->quantity != f.quantity || !coincide(*t->row, *f.row))
      continue;
    skip =
        f.option.algorithm == schema::Algorithm::PM || f.option.algorithm == schema::Algorithm::PLM;
    return fmt::format("{}, {} {}",
                       schema::to_string(std::min(f.option.algorithm, *twin_algorithm)),
                       schema::to_string(std::max(f.option.algorithm, *twin_algorithm)),
                       schema::to_string(f.option.contact));
  }
  return f.option.label();
}

/// The grade on F, with the grades an open read may have (open_read_grades).
std::string grade_cell(const RowFacts& f) {
  return f.grade ? std::string(schema::to_string(*f.grade)) + open_read_grades(f)
                 : std::string(kMissing);
}

TemplateData row_data(const RowFacts& f, const std::string& label, bool has_vf) {
  TemplateData d;
  d.set("option", label);
  d.set("c", format_value_and_error(f.row->values[0], f.errors[0]));
  d.set("m", format_value_and_error(f.row->values[1], f.errors[1]));
  d.set("f", format_value_and_error(f.row->values[2], f.errors[2]));
  d.set("has_vf", has_vf);
  d.set("vf", f.row->refinement
                  ? format_value_and_error(f.row->refinement->value, f.row->refinement->error)
                  : std::string(kMissing));
  d.set("grade", grade_cell(f));
  d.set("study_c", f.study_c ? "c" : "");
  d.set("trend", trend_word(f));
  d.set("to_bias", f.biased_limit.has_value());
  d.set("order", f.order ? fmt::format("{:.2f}", *f.order) : f.order_note);
  if (f.biased_limit) {
    TemplateData b("limit", format_error_resolved(f.biased_limit->error_percent));
    b.set("values_order", fmt::format("{:.2f}", f.biased_limit->order));
    d.set("biased", b);
  }
  d.set("credible", credible_cell(f, f.luck));
  return d;
}

/// The meshes with a value in any baseline row of the problem: "C, M" (false: none).
TemplateData meshes_given(const ResultsIndex& index, schema::ProblemId problem) {
  std::string out;
  for (std::size_t m = 0; m < kMeshes.size(); ++m) {
    const auto& rows = index.baseline_rows();
    if (std::any_of(rows.begin(), rows.end(), [&](const schema::RowVerdict* r) {
          return r->spec.problem == problem && r->values[m];
        }))
      out += (out.empty() ? "" : ", ") + std::string(schema::to_string(kMeshes[m]));
  }
  return text_or_false(out);
}

TemplateData quantity_tables(const ResultsIndex& index, const schema::ProblemRecord& problem,
                             const std::vector<const RowFacts*>& rows) {
  TemplateData tables{TemplateData::type::list};
  for (const auto& q : problem.quantities) {
    for (const Element e : schema::values<Element>()) {
      std::vector<const RowFacts*> these;
      bool has_vf = false;
      for (const RowFacts* f : rows) {
        if (f->quantity == q.quantity && f->element == e) {
          these.push_back(f);
          has_vf = has_vf || f->row->refinement.has_value();
        }
      }
      if (these.empty())
        continue;
      TemplateData t;
      t.set("quantity", q.definition_md);
      t.set("element", std::string(schema::to_string(e)));
      t.set("has_vf", has_vf);
      const auto exact = index.exact_of(*these.front()->row);
      t.set("exact", exact ? format_value(*exact) : std::string(kMissing));
      const auto study = index.study_exact_of(*these.front()->row);
      t.set("has_study_exact", study.has_value());
      t.set("study_exact", study ? format_value(*study) : std::string());
      TemplateData list{TemplateData::type::list};
      bool shared = false;
      for (const RowFacts* f : these) {
        bool skip = false;
        const std::string label = option_label(*f, these, skip);
        shared = shared || label.find(',') != std::string::npos;
        if (!skip)
          list.push_back(row_data(*f, label, has_vf));
      }
      t.set("rows", list);
      t.set("shared", shared);
      tables.push_back(t);
    }
  }
  return tables;
}

std::string divergence_table(const std::vector<DivergenceFacts>& singular, schema::ProblemId p) {
  constexpr Align r = Align::right, c = Align::center;
  MarkdownTable t({"Option", "C", "M", "F", "Eq. 47", "Strict", "Exponent", "Credible"},
                  {Align::left, r, r, r, c, c, c, c});
  for (const auto& d : singular) {
    if (d.problem == p)
      t.add_row({fmt::format("{} {}", schema::to_string(d.element), d.option.label()),
                 format_value(d.row->values[0]), format_value(d.row->values[1]),
                 format_value(d.row->values[2]), d.eq47 ? "holds" : "fails",
                 d.strict ? "diverges" : "no",
                 d.exponent ? fmt::format("{:.2f}", *d.exponent) : std::string(kMissing),
                 credible_cell(d, false)});
  }
  return t.render();
}

}  // namespace

std::string problem_page_file(schema::ProblemId problem) {
  return "problem-" + std::string(schema::to_string(problem)) + ".md";
}

std::string problem_page(const ResultsIndex& index, const schema::ProblemRecord& problem,
                         const std::vector<RowFacts>& rows,
                         const std::vector<DivergenceFacts>& singular,
                         const std::vector<const Figure*>& figures) {
  TemplateData d;
  d.set("label", std::string(schema::label(problem.id)));
  d.set("title", problem.title);
  d.set("description", problem.description);
  d.set("exact_source", problem.exact_source);
  d.set("has_study_tables", !problem.study_tables.empty());
  d.set("study_tables", problem.study_tables);
  d.set("singular", problem.singular);
  d.set("resolution", fmt::format("{:g} %", grading::kCoincidenceRelative * 100));
  const TemplateData tables = quantity_tables(index, problem, facts_of(rows, problem.id));
  d.set("has_tables", !tables.is_empty_list());
  d.set("tables", tables);
  d.set("meshes_given", meshes_given(index, problem.id));
  d.set("divergence", divergence_table(singular, problem.id));
  d.set("figures", template_list(figures, [](const Figure* f) { return figure_data(*f); }));
  return render_template(templates::problem_page, d);
}

}  // namespace cs::reports

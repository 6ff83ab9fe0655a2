#include "reports/tables/section_support.hpp"

#include "reports/tables/grade_tables.hpp"

namespace cs::reports {

std::vector<Slot> slots_of(const ResultsIndex& index) {
  std::vector<Slot> out;
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<schema::Element>())
        out.push_back({p->id, q.quantity, element});
    }
  }
  return out;
}

std::string rendered_if_any(const MarkdownTable& table) {
  return table.n_rows() == 0 ? std::string() : table.render();
}

TemplateData count_or_false(std::size_t n) {
  return text_or_false(n > 0 ? std::to_string(n) : "");
}

std::string per_problem_section(
    const ResultsIndex& index, schema::Quantity quantity, std::string_view text,
    const std::function<bool(const schema::ProblemRecord&, TemplateData&)>& fill) {
  TemplateData problems{TemplateData::type::list};
  for (const schema::ProblemRecord* p : index.problems()) {
    TemplateData d("label", std::string(schema::label(p->id)));
    d.set("title", p->title);
    d.set("source", p->exact_source);
    if (p->definition(quantity) != nullptr && fill(*p, d))
      problems.push_back(d);
  }
  if (problems.is_empty_list())
    return {};
  TemplateData d("problems", problems);
  d.set("marks_legend", evidence_marks_legend());
  return tidy_markdown(render_template(text, d));
}

}  // namespace cs::reports

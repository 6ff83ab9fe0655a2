#include "reports/tables/mesh_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// The first case of a problem on a mesh level with an element count (any element, option).
const schema::CaseResult* case_on(const ResultsIndex& index, schema::ProblemId problem,
                                  schema::MeshLevel mesh) {
  for (const auto& c : index.results().cases) {
    if (c.spec.problem == problem && c.spec.mesh == mesh && c.n_elements > 0)
      return &c;
  }
  return nullptr;
}

struct Differences {
  int count = 0, compared = 0;
  double largest_percent = 0.0;
  std::vector<std::string> problems;
};

/// "ours / study", with the signed difference where both are known and differ.
std::string count_cell(const schema::CaseResult* ours, std::optional<int> study,
                       Differences& differing) {
  if (ours == nullptr && !study)
    return kMissing;
  const std::string text =
      fmt::format("{} / {}", ours ? std::to_string(ours->n_elements) : kMissing,
                  study ? std::to_string(*study) : kMissing);
  if (ours == nullptr || !study)
    return text;
  ++differing.compared;
  if (ours->n_elements == *study)
    return text;
  ++differing.count;
  const double percent = 100.0 * (ours->n_elements - *study) / *study;
  differing.largest_percent = std::max(differing.largest_percent, std::abs(percent));
  return fmt::format("{} ({})", text, format_error_resolved(percent));
}

}  // namespace

std::string mesh_table_section(const ResultsIndex& index, const schema::StudyReference& study) {
  MarkdownTable table({"Problem", "C: ours / study", "M: ours / study", "F: ours / study",
                       "h at the contact (C / M / F)"});
  Differences differing;
  for (const schema::ProblemRecord* p : index.problems()) {
    std::array<std::string, 3> counts, sizes;
    bool any = false;
    const int before = differing.count;
    for (const auto mesh : kMeshes) {
      const schema::CaseResult* c = case_on(index, p->id, mesh);
      counts[mesh_index(mesh)] = count_cell(c, study.table1_elements(p->id, mesh), differing);
      sizes[mesh_index(mesh)] = c != nullptr && c->element_size_h > 0
                                    ? fmt::format("{:.4g}", c->element_size_h)
                                    : std::string(kMissing);
      any = any || c != nullptr;
    }
    if (differing.count > before)
      differing.problems.emplace_back(schema::label(p->id));
    if (any)
      table.add_row(
          {std::string(schema::label(p->id)), counts[0], counts[1], counts[2], join_meshes(sizes)});
  }
  if (table.n_rows() == 0)
    return {};
  TemplateData d("differing", std::to_string(differing.count));
  d.set("compared", std::to_string(differing.compared));
  d.set("largest",
        text_or_false(differing.count == 0 ? ""
                                           : fmt::format("{:.2f} %", differing.largest_percent)));
  d.set("problems", join_words(differing.problems, ", "));
  d.set("table", table.render());
  return tidy_markdown(render_template(templates::mesh_table, d));
}

}  // namespace cs::reports

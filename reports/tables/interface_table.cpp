#include "reports/tables/interface_table.hpp"

#include <algorithm>
#include <array>
#include <map>

#include <fmt/format.h>

#include "grading/interface_check_rules.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// Largest number of failing option sets listed.
constexpr std::size_t kListed = 40;

/// The cases the section covers: the study's option sets and the problems beyond it, once
/// (extrapolated twins share the contact solution of their patch-recovered case).
bool covered(const schema::CaseResult& c) {
  return c.interface && c.spec.recovery == schema::Recovery::spr;
}

struct Failing {
  std::string meshes;
  double worst = 0.0;
};

std::string summary_table(const ResultsIndex& index) {
  MarkdownTable table({"Check", "Measure", "Tolerance", "Cases checked", "Failing", "Worst case"});
  for (const auto& check : grading::interface_check_rules()) {
    int checked = 0, failing = 0;
    const schema::CaseResult* worst = nullptr;
    double worst_value = -1.0;
    for (const auto& c : index.results().cases) {
      if (!covered(c))
        continue;
      const auto v = check.measure(*c.interface);
      if (!v)
        continue;
      ++checked;
      failing += grading::fails(check, *v) ? 1 : 0;
      if (*v > worst_value) {
        worst_value = *v;
        worst = &c;
      }
    }
    table.add_row(
        {std::string(check.name), std::string(check.measure_text),
         fmt::format("{:g}", check.tolerance), std::to_string(checked), std::to_string(failing),
         worst != nullptr ? fmt::format("`{}`: {:.3g}", schema::case_id(worst->spec), worst_value)
                          : std::string(kMissing)});
  }
  return table.render();
}

/// The (problem, element, option, check) pairs that fail, in document order, with the meshes
/// on which they fail and the worst value.
MarkdownTable failing_table(const ResultsIndex& index) {
  std::map<std::array<std::string, 4>, Failing> failing;
  std::vector<std::array<std::string, 4>> order;
  for (const auto& c : index.results().cases) {
    if (!covered(c))
      continue;
    for (const auto& check : grading::interface_check_rules()) {
      const auto v = check.measure(*c.interface);
      if (!v || !grading::fails(check, *v))
        continue;
      const std::string variant = variant_of(c.spec);
      const std::array<std::string, 4> key{
          std::string(schema::label(c.spec.problem)),
          std::string(schema::to_string(c.spec.element)),
          fmt::format("{} {}{}{}", schema::to_string(c.spec.algorithm),
                      schema::to_string(c.spec.contact), variant.empty() ? "" : " ", variant),
          std::string(check.name)};
      auto [it, inserted] = failing.try_emplace(key);
      if (inserted)
        order.push_back(key);
      it->second.meshes += std::string(it->second.meshes.empty() ? "" : ", ") +
                           std::string(schema::to_string(c.spec.mesh));
      it->second.worst = std::max(it->second.worst, *v);
    }
  }
  MarkdownTable table({"Problem", "Element", "Option", "Check", "Meshes", "Worst"});
  for (const auto& key : order) {
    const Failing& f = failing.at(key);
    table.add_row({key[0], key[1], key[2], key[3], f.meshes, fmt::format("{:.3g}", f.worst)});
  }
  return table;
}

}  // namespace

std::string interface_section(const ResultsIndex& index) {
  const auto& cases = index.results().cases;
  if (std::none_of(cases.begin(), cases.end(), covered))
    return {};
  const MarkdownTable failing = failing_table(index);
  MarkdownTable listed(failing.header());
  for (std::size_t i = 0; i < failing.n_rows() && i < kListed; ++i)
    listed.add_row(failing.rows()[i]);
  TemplateData d;
  d.set("tolerance", fmt::format("{:g}", schema::kPenetrationTolerance));
  d.set("summary", summary_table(index));
  d.set("n_failing", text_or_false(failing.n_rows() > 0 ? std::to_string(failing.n_rows()) : ""));
  d.set("failing", listed.render());
  d.set("more", text_or_false(
                    failing.n_rows() > kListed ? std::to_string(failing.n_rows() - kListed) : ""));
  return tidy_markdown(render_template(templates::interface_table, d));
}

}  // namespace cs::reports

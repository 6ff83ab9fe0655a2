#include "reports/tables/interface_table.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <span>

#include <fmt/format.h>

#include "grading/interface_check_rules.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

/// Largest number of failing option sets listed.
constexpr std::size_t kListed = 40;

/// The cases the section covers: the study's option sets and the problems beyond it, once
/// (extrapolated twins share the contact solution of their patch-recovered case).
bool covered(const schema::CaseResult& c) {
  return c.interface && c.spec.recovery == schema::Recovery::spr;
}

/// "FP<sub>p</sub>, IF<sub>p</sub> (120 cases)" in the report's problem order, or "—".
std::string unmeasured_text(const ResultsIndex& index,
                            const std::map<schema::ProblemId, int>& unmeasured) {
  std::vector<std::string> labels;
  int cases = 0;
  for (const schema::ProblemRecord* p : index.problems()) {
    if (const auto it = unmeasured.find(p->id); it != unmeasured.end()) {
      labels.emplace_back(schema::label(p->id));
      cases += it->second;
    }
  }
  return labels.empty() ? std::string(kMissing)
                        : fmt::format("{} ({} cases)", join_words(labels, ", "), cases);
}

std::string summary_table(const ResultsIndex& index) {
  MarkdownTable table({"Check", "Measure", "Tolerance", "Cases checked", "Failing", "Worst case",
                       "Not measured on"});
  for (const auto& check : grading::interface_check_rules()) {
    int checked = 0, failing = 0;
    const schema::CaseResult* worst = nullptr;
    double worst_value = -1.0;
    std::map<schema::ProblemId, int> unmeasured;  // cases the check does not apply to
    for (const auto& c : index.results().cases) {
      if (!covered(c))
        continue;
      const std::optional<double> v = check.measure(*c.interface);
      if (!v) {
        ++unmeasured[c.spec.problem];
        continue;
      }
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
                          : std::string(kMissing),
         unmeasured_text(index, unmeasured)});
  }
  return table.render();
}

/// A (problem, element, option, check) that fails, the meshes on which it does and its worst
/// value.
struct Failing {
  std::array<std::string, 4> key;
  std::string meshes;
  double worst = 0.0;
};

/// The failing checks in document order.
std::vector<Failing> failing_checks(const ResultsIndex& index) {
  std::vector<Failing> out;
  for (const auto& c : index.results().cases) {
    for (const auto& check : grading::interface_check_rules()) {
      const auto v = covered(c) ? check.measure(*c.interface) : std::nullopt;
      if (!v || !grading::fails(check, *v))
        continue;
      const std::string variant = variant_of(c.spec);
      const std::array<std::string, 4> key{
          std::string(schema::label(c.spec.problem)), name_of(c.spec.element),
          fmt::format("{} {}{}{}", schema::to_string(c.spec.algorithm),
                      schema::to_string(c.spec.contact), variant.empty() ? "" : " ", variant),
          std::string(check.name)};
      auto it = std::ranges::find(out, key, &Failing::key);
      if (it == out.end())
        it = out.insert(out.end(), Failing{key, {}, 0.0});
      it->meshes += (it->meshes.empty() ? "" : ", ") + name_of(c.spec.mesh);
      it->worst = std::max(it->worst, *v);
    }
  }
  return out;
}

}  // namespace

std::string interface_section(const ResultsIndex& index) {
  const auto& cases = index.results().cases;
  if (std::ranges::none_of(cases, covered))
    return {};
  const std::vector<Failing> failing = failing_checks(index);
  const MarkdownTable listed = table_of(
      {"Problem", "Element", "Option", "Check", "Meshes", "Worst"},
      std::span(failing).first(std::min(failing.size(), kListed)), [](const Failing& f) {
        return std::vector<std::string>{f.key[0], f.key[1], f.key[2],
                                        f.key[3], f.meshes, fmt::format("{:.3g}", f.worst)};
      });
  TemplateData d("tolerance", fmt::format("{:g}", schema::kPenetrationTolerance));
  d.set("summary", summary_table(index));
  d.set("n_failing", count_or_false(failing.size()));
  d.set("failing", listed.render());
  d.set("more", count_or_false(failing.size() - std::min(failing.size(), kListed)));
  return tidy_markdown(render_template(templates::interface_table, d));
}

}  // namespace cs::reports

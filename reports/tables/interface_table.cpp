#include "reports/tables/interface_table.hpp"

#include <cmath>
#include <map>

#include <fmt/format.h>

#include "grading/interface_check_rules.hpp"
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

std::string failing_table(const ResultsIndex& index, std::size_t& n_failing) {
  // (problem, element, option, check) -> meshes and worst value, in document order.
  std::map<std::string, Failing> failing;
  std::vector<std::string> order;
  for (const auto& c : index.results().cases) {
    if (!covered(c))
      continue;
    for (const auto& check : grading::interface_check_rules()) {
      const auto v = check.measure(*c.interface);
      if (!v || !grading::fails(check, *v))
        continue;
      const std::string variant = variant_of(c.spec);
      const std::string key = fmt::format(
          "{} | {} | {} {}{}{} | {}", schema::label(c.spec.problem),
          schema::to_string(c.spec.element), schema::to_string(c.spec.algorithm),
          schema::to_string(c.spec.contact), variant.empty() ? "" : " ", variant, check.name);
      auto [it, inserted] = failing.try_emplace(key);
      if (inserted)
        order.push_back(key);
      it->second.meshes += std::string(it->second.meshes.empty() ? "" : ", ") +
                           std::string(schema::to_string(c.spec.mesh));
      it->second.worst = std::max(it->second.worst, *v);
    }
  }
  n_failing = order.size();
  if (order.empty())
    return {};
  std::string out =
      "| Problem | Element | Option | Check | Meshes | Worst |\n| :-- | :-: | :-: | :-- | :-: | "
      ":-: |\n";
  for (std::size_t i = 0; i < order.size() && i < kListed; ++i) {
    const Failing& f = failing.at(order[i]);
    out += fmt::format("| {} | {} | {:.3g} |\n", order[i], f.meshes, f.worst);
  }
  if (order.size() > kListed)
    out += fmt::format("\n… and {} more (all in results.json, `interface` of each case).\n",
                       order.size() - kListed);
  return out;
}

}  // namespace

std::string interface_section(const ResultsIndex& index) {
  bool any = false;
  for (const auto& c : index.results().cases)
    any = any || covered(c);
  if (!any)
    return {};
  std::size_t n_failing = 0;
  const std::string failing = failing_table(index, n_failing);
  std::string out =
      fmt::format(
          "## Interface checks\n\n"
          "Beside the graded peak, every case's contact interface is checked as a reviewer "
          "would check any contact solution: the contact forces must carry the whole applied "
          "load; a frictionless contact cannot pull; the pressure must vanish beyond the exact "
          "contact patch (allowing one element for the discrete edge); and penetration must "
          "stay below {:g} of the element size (the study's default FTOLN). Values per case are "
          "in results.json (`interface`).\n\n",
          schema::kPenetrationTolerance) +
      summary_table(index) + "\n";
  if (n_failing == 0)
    return out + "No option set fails a check.\n\n";
  return out + fmt::format("{} (option set, check) pairs fail:\n\n", n_failing) + failing + "\n";
}

}  // namespace cs::reports

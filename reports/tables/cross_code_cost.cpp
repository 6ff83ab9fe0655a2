#include "reports/tables/cross_code_cost.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::CaseResult;

void add(CostLine& line, const CaseResult& ours, const CaseResult& other) {
  ++line.pairs;
  line.ours_seconds += ours.wall_seconds;
  line.other_seconds += other.wall_seconds;
  line.ours_peak_mb = std::max(line.ours_peak_mb, ours.peak_rss_mb);
  line.other_peak_mb = std::max(line.other_peak_mb, other.peak_rss_mb);
  if (other.status == schema::CaseStatus::converged)
    ++line.other_converged;
}

std::string ratio_text(const std::optional<double>& r) {
  return r ? fmt::format("{:.3g}", *r) : std::string(kMissing);
}

std::vector<std::string> cells(const CostLine& l) {
  return {l.label,
          std::to_string(l.pairs),
          std::to_string(l.other_converged),
          fmt::format("{:.3g}", l.ours_seconds),
          fmt::format("{:.3g}", l.other_seconds),
          ratio_text(l.time_ratio()),
          fmt::format("{:.0f}", l.ours_peak_mb),
          fmt::format("{:.0f}", l.other_peak_mb),
          ratio_text(l.memory_ratio())};
}

/// Our cases by same_case_key (one per key: the first, spr before other recoveries).
std::map<std::string, const CaseResult*> ours_by_key(const ResultsIndex& index) {
  std::map<std::string, const CaseResult*> out;
  for (const auto& c : index.results().cases) {
    if (schema::solver_label(c.spec) != builtin_solver_label())
      continue;
    auto [it, inserted] = out.emplace(same_case_key(c.spec), &c);
    if (!inserted && c.spec.recovery == schema::Recovery::spr &&
        it->second->spec.recovery != schema::Recovery::spr)
      it->second = &c;
  }
  return out;
}

CrossCodeCost compare(const ResultsIndex& index, const std::string& solver,
                      const std::map<std::string, const CaseResult*>& ours) {
  CrossCodeCost out;
  out.solver = solver;
  out.total.label = "all cases";
  out.total_both_converged.label = "cases both converged";
  std::map<std::pair<int, schema::MeshLevel>, CostLine> lines;
  std::map<schema::ProblemId, int> order;
  for (std::size_t i = 0; i < index.problems().size(); ++i)
    order[index.problems()[i]->id] = static_cast<int>(i);
  std::map<std::string, bool> seen;  // one pair per key (an other solver's recovery twin)
  for (const auto& c : index.results().cases) {
    if (schema::solver_label(c.spec) != solver)
      continue;
    const std::string key = same_case_key(c.spec);
    const auto it = ours.find(key);
    if (it == ours.end() || seen[key])
      continue;
    seen[key] = true;
    const int position = order.count(c.spec.problem) ? order[c.spec.problem] : 1000;
    CostLine& line = lines[{position, c.spec.mesh}];
    line.label =
        fmt::format("{} {}", schema::label(c.spec.problem), schema::to_string(c.spec.mesh));
    add(line, *it->second, c);
    add(out.total, *it->second, c);
    if (c.status == schema::CaseStatus::converged &&
        it->second->status == schema::CaseStatus::converged)
      add(out.total_both_converged, *it->second, c);
  }
  for (auto& [k, l] : lines)
    out.lines.push_back(std::move(l));
  return out;
}

}  // namespace

std::optional<double> CostLine::time_ratio() const {
  return ours_seconds > 0 ? std::optional(other_seconds / ours_seconds) : std::nullopt;
}

std::optional<double> CostLine::memory_ratio() const {
  return ours_peak_mb > 0 ? std::optional(other_peak_mb / ours_peak_mb) : std::nullopt;
}

std::vector<CrossCodeCost> cross_code_cost(const ResultsIndex& index) {
  const auto ours = ours_by_key(index);
  std::vector<CrossCodeCost> out;
  for (const auto& s : solvers_in(index)) {
    if (s == builtin_solver_label())
      continue;
    CrossCodeCost c = compare(index, s, ours);
    if (c.total.pairs > 0)
      out.push_back(std::move(c));
  }
  return out;
}

MarkdownTable cost_table(const CrossCodeCost& cost) {
  const std::string name = solver_display_name(cost.solver);
  MarkdownTable table({"Cases", "pairs", fmt::format("{} converged", name), "ours (s)",
                       fmt::format("{} (s)", name), "time ratio", "ours peak (MB)",
                       fmt::format("{} peak (MB)", name), "memory ratio"});
  for (const auto& l : cost.lines)
    table.add_row(cells(l));
  table.add_row(cells(cost.total));
  table.add_row(cells(cost.total_both_converged));
  return table;
}

}  // namespace cs::reports

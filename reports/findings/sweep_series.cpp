#include "reports/findings/sweep_series.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "reports/findings/extent_section.hpp"

namespace cs::reports {

std::string SweepSeries::option_label() const {
  std::string out =
      fmt::format("{} {}", schema::to_string(base.algorithm), schema::to_string(base.contact));
  if (base.target == schema::TargetKind::Rigid)
    out += ", rigid";
  if (base.recovery != schema::Recovery::spr)
    out += fmt::format(", {}", schema::to_string(base.recovery));
  for (const auto& [name, value] : base.overrides)
    out += fmt::format(", {}={}", name, format_swept_value(value));
  if (base.solver != schema::SolverKind::builtin)
    out += ", @" + schema::solver_label(base);
  return out;
}

std::optional<double> SweepSeries::error(const SweepPoint& point, schema::Quantity quantity) {
  for (const auto& q : point.result->quantities) {
    if (q.quantity == quantity && std::isfinite(q.error_percent))
      return q.error_percent;
  }
  return std::nullopt;
}

bool SweepSeries::converged(const SweepPoint& point) {
  return point.result->status == schema::CaseStatus::converged;
}

std::vector<std::string> swept_keys(const schema::ResultsDocument& doc) {
  std::vector<std::string> keys;
  const auto add = [&](const schema::RunInfo& run) {
    for (const auto& axis : run.sweep) {
      if (std::find(keys.begin(), keys.end(), axis.key) == keys.end())
        keys.push_back(axis.key);
    }
  };
  add(doc.run);
  for (const auto& [source, run] : doc.added_runs)  // files combined by `report --results`
    add(run);
  std::map<std::string, std::set<double>> seen;
  for (const auto& c : doc.cases) {
    if (in_extent_study(c.spec))  // the extent study has a section of its own
      continue;
    for (const auto& [name, value] : c.spec.overrides)
      seen[name].insert(value);
  }
  for (const auto& [name, values] : seen) {
    if (values.size() >= 2 && std::find(keys.begin(), keys.end(), name) == keys.end())
      keys.push_back(name);
  }
  return keys;
}

std::vector<SweepSeries> sweep_series(const schema::ResultsDocument& doc, const std::string& key) {
  std::map<std::string, std::size_t> slot;
  std::vector<SweepSeries> out;
  for (const auto& c : doc.cases) {
    const auto it = c.spec.overrides.find(key);
    if (it == c.spec.overrides.end())
      continue;
    schema::CaseSpec base = c.spec;
    base.overrides.erase(key);
    const auto [s, fresh] = slot.try_emplace(schema::case_id(base), out.size());
    if (fresh)
      out.push_back(SweepSeries{key, base, {}});
    out[s->second].points.push_back({it->second, &c});
  }
  for (auto& s : out) {
    std::stable_sort(s.points.begin(), s.points.end(),
                     [](const SweepPoint& a, const SweepPoint& b) { return a.value < b.value; });
  }
  return out;
}

bool on_finest_mesh(const SweepSeries& s, const std::vector<SweepSeries>& all) {
  for (const auto& o : all) {
    if (o.base.problem == s.base.problem && o.base.element == s.base.element &&
        o.base.mesh > s.base.mesh)
      return false;
  }
  return true;
}

std::vector<double> swept_values(const std::vector<SweepSeries>& series) {
  std::set<double> values;
  for (const auto& s : series) {
    for (const auto& p : s.points)
      values.insert(p.value);
  }
  return {values.begin(), values.end()};
}

std::string format_swept_value(double value) {
  return fmt::format("{:g}", value);
}

std::vector<SweepPanel> sweep_panels(const std::vector<SweepSeries>& series) {
  using Key = std::tuple<schema::ProblemId, schema::Quantity, schema::MeshLevel, schema::Element>;
  std::map<Key, std::size_t> slot;
  std::vector<SweepPanel> panels;
  for (const auto& s : series) {
    if (s.points.empty() || !on_finest_mesh(s, series))
      continue;
    for (const auto& q : s.points.front().result->quantities) {
      if (q.quantity == schema::Quantity::contact_half_width)
        continue;  // graded apart: it moves by whole nodes
      const Key key{s.base.problem, q.quantity, s.base.mesh, s.base.element};
      const auto [it, fresh] = slot.try_emplace(key, panels.size());
      if (fresh)
        panels.push_back({s.base.problem, q.quantity, s.base.mesh, s.base.element, {}});
      panels[it->second].series.push_back(&s);
    }
  }
  return panels;
}

}  // namespace cs::reports

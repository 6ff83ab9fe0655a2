#include "reports/findings/parameter_series.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace cs::reports {

const SeriesPoint* ParameterSeries::at(double parameter) const {
  const auto it = std::ranges::find(points, parameter, &SeriesPoint::parameter);
  return it == points.end() ? nullptr : &*it;
}

std::string ParameterSeries::option_label() const {
  std::string out =
      fmt::format("{} {}", schema::to_string(spec.algorithm), schema::to_string(spec.contact));
  if (spec.target == schema::TargetKind::Rigid)
    out += ", rigid";
  if (spec.recovery != schema::Recovery::spr)
    out += fmt::format(", {}", schema::to_string(spec.recovery));
  for (const auto& [name, value] : spec.overrides)
    out += fmt::format(", {}={}", name, format_parameter(value));
  if (spec.solver != schema::SolverKind::builtin)
    out += ", @" + schema::solver_label(spec);
  return out;
}

std::vector<std::string> ParameterSeries::label_cells() const {
  return {name_of(spec.problem), name_of(quantity), name_of(spec.mesh), name_of(spec.element),
          option_label()};
}

std::string ParameterSeries::label() const {
  return fmt::format("{}", fmt::join(label_cells(), " "));
}

std::optional<std::pair<double, double>> ParameterSeries::error_range() const {
  std::optional<std::pair<double, double>> range;
  for (const auto& p : points) {
    if (p.error && p.converged())
      range = range ? std::make_pair(std::min(range->first, *p.error),
                                     std::max(range->second, *p.error))
                    : std::make_pair(*p.error, *p.error);
  }
  return range;
}

ParameterSeries& SeriesGroups::of(const std::string& id, const ParameterSeries& first) {
  const auto [it, fresh] = slot_.try_emplace(id, series_.size());
  if (fresh)
    series_.push_back(first);
  return series_[it->second];
}

std::vector<ParameterSeries> SeriesGroups::sorted() && {
  for (auto& s : series_)
    std::ranges::stable_sort(s.points, {}, &SeriesPoint::parameter);
  return std::move(series_);
}

std::vector<double> parameter_values(const SeriesRefs& series) {
  std::set<double> values;
  for (const ParameterSeries* s : series) {
    for (const auto& p : s->points)
      values.insert(p.parameter);
  }
  return {values.begin(), values.end()};
}

std::string format_parameter(double value) {
  return fmt::format("{:g}", value);
}

std::string parameter_list(const std::vector<double>& values) {
  return values.empty() ? "none" : fmt::format("{:g}", fmt::join(values, ", "));
}

std::string parameter_window(const std::vector<double>& chosen, const std::vector<double>& all) {
  const auto first = chosen.empty() ? all.end() : std::find(all.begin(), all.end(), chosen.front());
  const bool contiguous = chosen.size() >= 2 && all.end() - first >= std::ssize(chosen) &&
                          std::equal(chosen.begin(), chosen.end(), first);
  return contiguous ? fmt::format("{} to {}", format_parameter(chosen.front()),
                                  format_parameter(chosen.back()))
                    : parameter_list(chosen);
}

MarkdownTable parameter_table(std::vector<std::string> lead, std::vector<Align> align,
                              const std::vector<double>& values) {
  for (double v : values) {
    lead.push_back(format_parameter(v));
    align.push_back(Align::right);
  }
  return MarkdownTable(std::move(lead), std::move(align));
}

}  // namespace cs::reports

#include "reports/findings/extent_section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/render/template_text.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

constexpr const char* kExtentKey = "extent";
constexpr const char* kGapKey = "half_space_gap";

/// One option set of one problem's graded quantity, at every extent present (1 = baseline).
struct ExtentSeries {
  schema::ProblemId problem{};
  schema::Quantity quantity{};
  schema::Element element{};
  Option option;
  std::map<double, const schema::RowVerdict*> by_extent;
  /// The same cases with `half_space_gap=1` (gaps along the block's own normal), by extent.
  std::map<double, const schema::RowVerdict*> block_normal;
};

bool ours_with_patch_recovery(const schema::CaseSpec& s) {
  return s.solver == schema::SolverKind::builtin && s.target == schema::TargetKind::Discretized &&
         s.recovery == schema::Recovery::spr;
}

/// A case with `extent` and `half_space_gap=1` as its only overrides.
bool in_gap_study(const schema::CaseSpec& s) {
  return s.overrides.size() == 2 && s.overrides.contains(kExtentKey) &&
         s.overrides.contains(kGapKey) && s.overrides.at(kGapKey) == 1.0 &&
         ours_with_patch_recovery(s);
}

/// A case with `extent` as its only override.
bool in_plain_extent_study(const schema::CaseSpec& s) {
  return s.overrides.size() == 1 && s.overrides.contains(kExtentKey) && ours_with_patch_recovery(s);
}

std::optional<double> extent_of(const schema::CaseSpec& s) {
  if (!in_plain_extent_study(s))
    return std::nullopt;
  return s.overrides.at(kExtentKey);
}

std::string series_key(const schema::RowVerdict& r) {
  const schema::CaseSpec& s = r.spec;
  return fmt::format("{}/{}/{}/{}/{}", schema::to_string(s.problem), schema::to_string(r.quantity),
                     schema::to_string(s.element), schema::to_string(s.algorithm),
                     schema::to_string(s.contact));
}

std::vector<ExtentSeries> collect_series(const ResultsIndex& index) {
  std::map<std::string, ExtentSeries> by_key;
  std::vector<std::string> order;
  for (const schema::RowVerdict* r : index.variant_rows()) {
    const auto extent = extent_of(r->spec);
    // the contact half-width moves in half-element steps: the peak stresses decide the extent
    if (!extent || r->quantity == schema::Quantity::contact_half_width)
      continue;
    const schema::CaseSpec& s = r->spec;
    const std::string key = series_key(*r);
    auto [it, fresh] = by_key.try_emplace(key);
    if (fresh) {
      order.push_back(key);
      it->second = {s.problem, r->quantity, s.element, {s.algorithm, s.contact}, {}};
      if (const schema::RowVerdict* base =
              index.row(s.problem, r->quantity, s.element, it->second.option))
        it->second.by_extent[1.0] = base;
    }
    it->second.by_extent[*extent] = r;
  }
  // The half-space gap's rows join the series of the same option (none without one).
  for (const schema::RowVerdict* r : index.variant_rows()) {
    if (!in_gap_study(r->spec) || r->quantity == schema::Quantity::contact_half_width)
      continue;
    if (auto it = by_key.find(series_key(*r)); it != by_key.end())
      it->second.block_normal[r->spec.overrides.at(kExtentKey)] = r;
  }
  std::vector<ExtentSeries> out;
  for (const auto& k : order)
    out.push_back(by_key.at(k));
  return out;
}

std::optional<double> fine_value(const schema::RowVerdict& r) {
  return r.values[mesh_index(kFinestMesh)];
}

std::optional<double> richardson(const schema::RowVerdict& r) {
  if (r.estimate && r.estimate->asymptotic)
    return r.estimate->richardson;
  return std::nullopt;
}

std::optional<double> percent_of(std::optional<double> value, std::optional<double> exact) {
  if (!value || !exact || *exact == 0.0)
    return std::nullopt;
  return 100.0 * (*value / *exact - 1.0);
}

std::string percent_cell(std::optional<double> p) {
  return p ? format_error_resolved(*p) : std::string(kMissing);
}

std::string extent_label(double k) {
  return fmt::format("{:g}", k);
}

/// Largest relative change (percent) of the fine-mesh value from extent k to the next extent,
/// over the series that have both; nullopt when none has.
std::optional<double> change_after(const std::vector<const ExtentSeries*>& series, double k) {
  std::optional<double> worst;
  for (const ExtentSeries* s : series) {
    const auto at = s->by_extent.find(k);
    if (at == s->by_extent.end())
      continue;
    const auto next = std::next(at);
    if (next == s->by_extent.end())
      continue;
    const auto a = fine_value(*at->second), b = fine_value(*next->second);
    if (!a || !b || *a == 0.0)
      continue;
    const double change = 100.0 * std::abs(*b / *a - 1.0);
    worst = std::max(worst.value_or(0.0), change);
  }
  return worst;
}

/// The extents present in any series, increasing.
std::vector<double> extents_of(const std::vector<const ExtentSeries*>& series) {
  std::vector<double> ks;
  for (const ExtentSeries* s : series) {
    for (const auto& [k, row] : s->by_extent)
      ks.push_back(k);
  }
  std::sort(ks.begin(), ks.end());
  ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
  return ks;
}

/// The largest change (percent) of a fine value between consecutive extents from ks[i] on.
std::optional<double> largest_change_from(const std::vector<const ExtentSeries*>& series,
                                          const std::vector<double>& ks, std::size_t i) {
  std::optional<double> worst;
  for (std::size_t j = i; j + 1 < ks.size(); ++j) {
    if (const auto change = change_after(series, ks[j]))
      worst = std::max(worst.value_or(0.0), *change);
  }
  return worst;
}

/// The smallest extent from which on no series' fine value changes by kHalfSpaceChangePercent
/// between any two consecutive extents run.
std::optional<double> half_space_extent(const std::vector<const ExtentSeries*>& series) {
  const auto ks = extents_of(series);
  for (std::size_t i = 0; i + 1 < ks.size(); ++i) {
    const auto change = largest_change_from(series, ks, i);
    if (change && *change < kHalfSpaceChangePercent)
      return ks[i];
  }
  return std::nullopt;
}

std::vector<std::string> mesh_errors(const schema::RowVerdict& row, std::optional<double> exact) {
  std::vector<std::string> cells;
  for (std::size_t m = 0; m < 3; ++m)
    cells.push_back(percent_cell(percent_of(row.values[m], exact)));
  return cells;
}

std::string option_of(const ExtentSeries& s) {
  return fmt::format("{} {} {}", schema::label(s.quantity), schema::to_string(s.element),
                     s.option.label());
}

/// Per series and extent: the C, M, F values, the Richardson limit, F against the limit and the
/// change of F from the previous extent.
std::string series_table(const ResultsIndex& index,
                         const std::vector<const ExtentSeries*>& series) {
  constexpr Align l = Align::left, c = Align::center, r = Align::right;
  MarkdownTable t({"Quantity", "Element", "Option", "Extent", "C", "M", "F", "Richardson limit",
                   "F − limit", "Change of F from the previous extent"},
                  {l, c, l, r, r, r, r, r, r, r});
  for (const ExtentSeries* s : series) {
    std::optional<double> previous;
    for (const auto& [k, row] : s->by_extent) {
      const auto exact = index.exact_of(*row);
      const auto lim = richardson(*row);
      const auto f = fine_value(*row);
      const auto with_error = [&](std::optional<double> v) {
        return v ? fmt::format("{} ({})", format_value(*v), percent_cell(percent_of(v, exact)))
                 : std::string(kMissing);
      };
      t.add_row({std::string(schema::label(s->quantity)),
                 std::string(schema::to_string(s->element)), s->option.label(), extent_label(k),
                 with_error(row->values[0]), with_error(row->values[1]), with_error(row->values[2]),
                 lim ? with_error(lim) : (row->estimate ? row->estimate->note : kMissing),
                 percent_cell(lim && f ? percent_of(f, lim) : std::nullopt),
                 percent_cell(previous && f ? percent_of(f, previous) : std::nullopt)});
      previous = f;
    }
  }
  return t.render();
}

std::vector<ErrorSplit> error_splits(const ResultsIndex& index,
                                     const std::vector<const ExtentSeries*>& series) {
  std::vector<ErrorSplit> out;
  for (const ExtentSeries* s : series) {
    if (s->by_extent.size() < 2 || !s->by_extent.contains(1.0))
      continue;
    const schema::RowVerdict& study = *s->by_extent.at(1.0);
    const auto& [k_max, widest] = *s->by_extent.rbegin();
    const auto exact = index.exact_of(study);
    const auto lim1 = richardson(study), lim_max = richardson(*widest), f1 = fine_value(study);
    if (!exact || !lim1 || !lim_max || !f1)
      continue;
    out.push_back({option_of(*s), *percent_of(f1, exact), 100.0 * (*lim1 - *lim_max) / *exact,
                   100.0 * (*f1 - *lim1) / *exact, *percent_of(lim_max, exact), k_max});
  }
  return out;
}

/// Of the extents at or beyond `from`, the one with the most series, the widest among equals
/// (every option is run at the widest all-options extent, a few only further out).
double widest_extent_of_most_options(const std::vector<const ExtentSeries*>& series, double from) {
  double best = from;
  std::size_t most = 0;
  for (double k : extents_of(series)) {
    const auto n = static_cast<std::size_t>(
        std::count_if(series.begin(), series.end(),
                      [k](const ExtentSeries* s) { return s->by_extent.contains(k); }));
    if (k >= from && n >= most) {
      most = n;
      best = k;
    }
  }
  return best;
}

std::optional<double> widest_compared_extent(const std::vector<const ExtentSeries*>& series) {
  std::optional<double> widest;
  for (const ExtentSeries* s : series) {
    for (const auto& [k, row] : s->block_normal) {
      if (s->by_extent.contains(k))
        widest = std::max(widest.value_or(k), k);
    }
  }
  return widest;
}

ExtentFacts facts_of(const ResultsIndex& index, schema::ProblemId problem,
                     const std::vector<const ExtentSeries*>& series) {
  ExtentFacts f;
  f.problem = problem;
  const bool singular = index.singular(problem);
  if (!singular)
    f.splits = error_splits(index, series);
  const auto ks = extents_of(series);
  f.half_space = half_space_extent(series);
  if (f.half_space) {
    const auto i =
        static_cast<std::size_t>(std::find(ks.begin(), ks.end(), *f.half_space) - ks.begin());
    f.change_after_half_space = largest_change_from(series, ks, i).value_or(0.0);
    if (!singular)
      f.grades_extent = widest_extent_of_most_options(series, *f.half_space);
  } else if (ks.size() >= 2) {
    f.second_widest = ks[ks.size() - 2];
    f.widest = ks.back();
    f.last_change = change_after(series, ks[ks.size() - 2]).value_or(0.0);
  }
  if (!singular)
    f.gap_extent = widest_compared_extent(series);
  return f;
}

/// One template row per series for which `cells` gives one, labelled with its option.
template <typename Cells>
TemplateData pair_rows(const std::vector<const ExtentSeries*>& series, Cells&& cells) {
  TemplateData list{TemplateData::type::list};
  for (const ExtentSeries* s : series) {
    if (auto d = cells(*s)) {
      d->set("quantity", std::string(schema::label(s->quantity)));
      d->set("element", std::string(schema::to_string(s->element)));
      d->set("option", s->option.label());
      list.push_back(*d);
    }
  }
  return list;
}

TemplateData problem_data(const ResultsIndex& index, const ExtentFacts& f,
                          const std::vector<const ExtentSeries*>& series) {
  const schema::ProblemRecord* record = index.problem(f.problem);
  TemplateData d;
  d.set("label", std::string(schema::label(f.problem)));
  d.set("description", record ? " — " + record->description : std::string());
  d.set("singular", index.singular(f.problem));
  d.set("exact", format_value(index.exact_of(*series.front()->by_extent.begin()->second)));
  d.set("exact_source", record ? record->exact_source : std::string());
  d.set("series", series_table(index, series));
  d.set("splits", template_list(f.splits, [](const ErrorSplit& s) {
          TemplateData t;
          t.set("option", s.option);
          t.set("f_error", format_error_resolved(s.f_error));
          t.set("block", format_error_resolved(s.block));
          t.set("discretization", format_error_resolved(s.discretization));
          t.set("remaining", format_error_resolved(s.remaining));
          t.set("widest", extent_label(s.widest));
          return t;
        }));
  const auto num = [](const std::optional<double>& v) { return v ? extent_label(*v) : kMissing; };
  const auto pct = [](const std::optional<double>& v) {
    return fmt::format("{:.3f}", v.value_or(0.0));
  };
  d.set("has_half_space", f.half_space.has_value());
  d.set("half_space", num(f.half_space));
  d.set("change_after", pct(f.change_after_half_space));
  d.set("threshold", fmt::format("{:g}", kHalfSpaceChangePercent));
  d.set("no_half_space", f.last_change.has_value());
  d.set("second_widest", num(f.second_widest));
  d.set("widest", num(f.widest));
  d.set("last_change", pct(f.last_change));
  d.set("grades_extent", num(f.grades_extent));
  if (f.grades_extent) {
    const double k = *f.grades_extent;
    d.set("grades", pair_rows(series, [&](const ExtentSeries& s) -> std::optional<TemplateData> {
            if (!s.by_extent.contains(k) || !s.by_extent.contains(1.0))
              return std::nullopt;
            const schema::RowVerdict *base = s.by_extent.at(1.0), *at = s.by_extent.at(k);
            const auto exact = index.exact_of(*base);
            TemplateData t;
            t.set("study", percent_cell(percent_of(fine_value(*base), exact)));
            t.set("study_grade", format_grade_cell(index, base));
            t.set("wide", percent_cell(percent_of(fine_value(*at), exact)));
            t.set("wide_grade", format_grade_cell(index, at));
            return t;
          }));
  }
  d.set("has_grades", d.get("grades") && !d.get("grades")->is_empty_list());
  d.set("gap_extent", num(f.gap_extent));
  if (f.gap_extent) {
    const double k = *f.gap_extent;
    d.set("gap_rows", pair_rows(series, [&](const ExtentSeries& s) -> std::optional<TemplateData> {
            if (!s.by_extent.contains(k) || !s.block_normal.contains(k))
              return std::nullopt;
            const schema::RowVerdict *plain = s.by_extent.at(k), *block = s.block_normal.at(k);
            const auto exact = index.exact_of(*plain);
            TemplateData t;
            t.set("target", fmt::format("{}", fmt::join(mesh_errors(*plain, exact), ", ")));
            t.set("target_grade", format_grade_cell(index, plain));
            t.set("block", fmt::format("{}", fmt::join(mesh_errors(*block, exact), ", ")));
            t.set("block_grade", format_grade_cell(index, block));
            return t;
          }));
  }
  d.set("has_gap", d.get("gap_rows") && !d.get("gap_rows")->is_empty_list());
  return d;
}

std::vector<std::pair<ExtentFacts, std::vector<const ExtentSeries*>>> by_problem(
    const ResultsIndex& index, const std::vector<ExtentSeries>& all) {
  std::vector<std::pair<ExtentFacts, std::vector<const ExtentSeries*>>> out;
  for (const schema::ProblemRecord* p : index.problems()) {
    std::vector<const ExtentSeries*> series;
    for (const auto& s : all) {
      if (s.problem == p->id)
        series.push_back(&s);
    }
    if (!series.empty())
      out.emplace_back(facts_of(index, p->id, series), series);
  }
  return out;
}

}  // namespace

bool in_extent_study(const schema::CaseSpec& s) {
  return in_plain_extent_study(s) || in_gap_study(s);
}

std::vector<ExtentFacts> extent_facts(const ResultsIndex& index) {
  std::vector<ExtentFacts> out;
  for (auto& [facts, series] : by_problem(index, collect_series(index)))
    out.push_back(facts);
  return out;
}

std::string extent_section(const ResultsIndex& index) {
  const std::vector<ExtentSeries> all = collect_series(index);
  if (all.empty())
    return {};
  TemplateData problems{TemplateData::type::list};
  for (const auto& [facts, series] : by_problem(index, all))
    problems.push_back(problem_data(index, facts, series));
  TemplateData d;
  d.set("problems", problems);
  return render_template(templates::extent_section, d);
}

}  // namespace cs::reports

#include "reports/findings/extent_section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/accuracy.hpp"
#include "grading/richardson.hpp"
#include "reports/findings/parameter_series.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

constexpr const char* kExtentKey = "extent";
constexpr const char* kGapKey = "half_space_gap";

/// The point of a row at its extent: the F value and its error.
SeriesPoint row_point(double extent, const schema::RowVerdict& row) {
  const std::size_t f = mesh_index(kFinestMesh);
  return {.parameter = extent, .value = row.values[f], .error = row.errors[f], .row = &row};
}

/// Per option set and stress quantity, the F values over the extent (the study's extent 1 is
/// the baseline row): the plain series (no override left), and the half-space gap's series
/// (`half_space_gap=1` left), each in document order of its first row.
std::vector<ParameterSeries> collect_series(const ResultsIndex& index) {
  SeriesGroups groups;
  for (const schema::RowVerdict* r : index.variant_rows()) {
    // the contact half-width moves in half-element steps: the peak stresses decide the extent
    if (!in_extent_study(r->spec) || r->quantity == schema::Quantity::contact_half_width)
      continue;
    const bool plain = r->spec.overrides.size() == 1;  // no half-space gap
    ParameterSeries first{r->spec, r->quantity, {}};
    first.spec.overrides.erase(kExtentKey);
    const std::string id = schema::case_key(first.spec) + "/" + name_of(r->quantity);
    ParameterSeries& s = groups.of(id, first);
    const schema::RowVerdict* base = index.row(r->spec.problem, r->quantity, r->spec.element,
                                               {r->spec.algorithm, r->spec.contact});
    if (s.points.empty() && plain && base)
      s.points.push_back(row_point(1.0, *base));
    const SeriesPoint point = row_point(r->spec.overrides.at(kExtentKey), *r);
    const auto same = std::ranges::find(s.points, point.parameter, &SeriesPoint::parameter);
    if (same == s.points.end())
      s.points.push_back(point);
    else
      *same = point;  // in place of the baseline row at extent 1
  }
  return std::move(groups).sorted();
}

/// The half-space gap's series of a plain series, or nullptr.
const ParameterSeries* block_normal_of(const std::vector<ParameterSeries>& all,
                                       const ParameterSeries& s) {
  schema::CaseSpec spec = s.spec;
  spec.overrides[kGapKey] = 1.0;
  const auto it = std::ranges::find_if(all, [&](const ParameterSeries& o) {
    return o.quantity == s.quantity && schema::case_key(o.spec) == schema::case_key(spec);
  });
  return it == all.end() ? nullptr : &*it;
}

/// The row's Richardson limit where it can be trusted (trusted_estimate).
std::optional<double> richardson(const schema::RowVerdict& r) {
  const grading::TrustedEstimate t = grading::trusted_estimate(r);
  return t.estimate ? t.estimate->richardson : std::nullopt;
}

std::optional<double> percent_of(std::optional<double> value, std::optional<double> exact) {
  if (!value || !exact || *exact == 0.0)
    return std::nullopt;
  return grading::error_percent(*value, *exact);
}

/// Per extent k, the largest relative change (percent) of a fine-mesh value from k to the next
/// extent of its series, over the series that have both.
std::map<double, double> steps_of(const SeriesRefs& series) {
  std::map<double, double> steps;
  for (const ParameterSeries* s : series) {
    for (std::size_t i = 0; i + 1 < s->points.size(); ++i) {
      const auto a = s->points[i].value, b = s->points[i + 1].value;
      if (a && b && *a != 0.0)
        steps[s->points[i].parameter] =
            std::max(steps[s->points[i].parameter], 100.0 * std::abs(*b / *a - 1.0));
    }
  }
  return steps;
}

std::string mesh_errors(const schema::RowVerdict& row, std::optional<double> exact) {
  std::vector<std::string> cells;
  for (std::size_t m = 0; m < 3; ++m)
    cells.push_back(format_error_resolved(percent_of(row.values[m], exact)));
  return fmt::format("{}", fmt::join(cells, ", "));
}

/// Per series and extent: the C, M, F values, the Richardson limit, F against the limit and the
/// change of F from the previous extent.
std::string series_table(const ResultsIndex& index, const SeriesRefs& series) {
  constexpr Align l = Align::left, c = Align::center, r = Align::right;
  MarkdownTable t({"Quantity", "Element", "Option", "Extent", "C", "M", "F", "Richardson limit",
                   "F − limit", "Change of F from the previous extent"},
                  {l, c, l, r, r, r, r, r, r, r});
  for (const ParameterSeries* s : series) {
    const SeriesPoint* previous = nullptr;
    for (const SeriesPoint& p : s->points) {
      const schema::RowVerdict& row = *p.row;
      const auto exact = index.exact_of(row);
      const auto lim = richardson(row);
      const auto with_error = [&](std::optional<double> v) {
        return v ? fmt::format("{} ({})", format_value(*v),
                               format_error_resolved(percent_of(v, exact)))
                 : std::string(kMissing);
      };
      t.add_row({std::string(schema::label(s->quantity)), name_of(s->spec.element),
                 s->option_label(), format_parameter(p.parameter), with_error(row.values[0]),
                 with_error(row.values[1]), with_error(row.values[2]),
                 lim ? with_error(lim) : grading::trusted_estimate(row).note,
                 format_error_resolved(percent_of(p.value, lim)),
                 previous ? fmt::format("{} (from {})",
                                        format_error_resolved(percent_of(p.value, previous->value)),
                                        format_parameter(previous->parameter))
                          : std::string(kMissing)});
      previous = &p;
    }
  }
  return t.render();
}

std::vector<ErrorSplit> error_splits(const ResultsIndex& index, const SeriesRefs& series) {
  std::vector<ErrorSplit> out;
  for (const ParameterSeries* s : series) {
    const SeriesPoint* study = s->at(1.0);
    if (s->points.size() < 2 || !study)
      continue;
    const SeriesPoint& widest = s->points.back();
    const auto exact = index.exact_of(*study->row);
    const auto lim1 = richardson(*study->row), lim_max = richardson(*widest.row);
    const auto f1 = study->value;
    if (!exact || *exact == 0.0 || !lim1 || !lim_max || !f1)
      continue;
    out.push_back({fmt::format("{} {} {}", schema::label(s->quantity),
                               schema::to_string(s->spec.element), s->option_label()),
                   *percent_of(f1, exact), 100.0 * (*lim1 - *lim_max) / std::abs(*exact),
                   100.0 * (*f1 - *lim1) / std::abs(*exact), *percent_of(lim_max, exact),
                   widest.parameter});
  }
  return out;
}

/// Of the extents at or beyond `from`, the one with the most series, the widest among equals
/// (every option is run at the widest all-options extent, a few only further out).
double widest_extent_of_most_options(const SeriesRefs& series, double from) {
  double best = from;
  std::ptrdiff_t most = 0;
  for (double k : parameter_values(series)) {
    const auto n =
        std::ranges::count_if(series, [k](const ParameterSeries* s) { return s->at(k); });
    if (k >= from && n >= most) {
      most = n;
      best = k;
    }
  }
  return best;
}

std::optional<double> widest_compared_extent(const std::vector<ParameterSeries>& all,
                                             const SeriesRefs& series) {
  std::optional<double> widest;
  for (const ParameterSeries* s : series) {
    const ParameterSeries* twin = block_normal_of(all, *s);
    for (const SeriesPoint& p : twin ? twin->points : std::vector<SeriesPoint>{}) {
      if (s->at(p.parameter))
        widest = std::max(widest.value_or(p.parameter), p.parameter);
    }
  }
  return widest;
}

ExtentFacts facts_of(const ResultsIndex& index, schema::ProblemId problem,
                     const std::vector<ParameterSeries>& all, const SeriesRefs& series) {
  ExtentFacts f;
  f.problem = problem;
  const bool singular = index.singular(problem);
  if (!singular) {
    f.splits = error_splits(index, series);
    f.gap_extent = widest_compared_extent(all, series);
  }
  const auto ks = parameter_values(series);
  const auto steps = steps_of(series);
  for (std::size_t i = 0; i + 1 < ks.size() && !f.half_space; ++i) {
    std::optional<double> change;  // the largest step from ks[i] on
    for (auto it = steps.lower_bound(ks[i]); it != steps.end(); ++it)
      change = std::max(change.value_or(0.0), it->second);
    if (change && *change < kHalfSpaceChangePercent)
      std::tie(f.half_space, f.change_after_half_space) = std::make_pair(ks[i], *change);
  }
  f.n_series = static_cast<int>(series.size());
  if (f.half_space) {
    f.half_space_series = static_cast<int>(std::ranges::count_if(series, [&](const auto* s) {
      return std::ranges::count_if(s->points, [&](const SeriesPoint& p) {
               return p.parameter >= *f.half_space;
             }) >= 2;
    }));
  }
  if (f.half_space && !singular) {
    f.grades_extent = widest_extent_of_most_options(series, *f.half_space);
  } else if (!f.half_space && ks.size() >= 2) {
    f.second_widest = ks[ks.size() - 2];
    f.widest = ks.back();
    f.last_change = steps.contains(ks[ks.size() - 2]) ? steps.at(ks[ks.size() - 2]) : 0.0;
  }
  return f;
}

/// One template row per series with a point at `first_at` and a `second` point (false for none):
/// the quantity, element and option, and of both points the F errors (`all_meshes`: C, M, F)
/// against the exact value of the first, and their grades.
template <typename Second>
TemplateData pair_rows(const ResultsIndex& index, const SeriesRefs& series, double first_at,
                       Second&& second, bool all_meshes) {
  TemplateData list{TemplateData::type::list};
  for (const ParameterSeries* s : series) {
    const SeriesPoint *a = s->at(first_at), *b = a ? second(*s) : nullptr;
    if (!b)
      continue;
    const auto exact = index.exact_of(*a->row);
    const auto errors = [&](const SeriesPoint* p) {
      return all_meshes ? mesh_errors(*p->row, exact)
                        : format_error_resolved(percent_of(p->value, exact));
    };
    TemplateData d;
    d.set("quantity", std::string(schema::label(s->quantity)));
    d.set("element", name_of(s->spec.element));
    d.set("option", s->option_label());
    d.set("first", errors(a));
    d.set("first_grade", format_marked_grade_cell(index, a->row));
    d.set("second", errors(b));
    d.set("second_grade", format_marked_grade_cell(index, b->row));
    list.push_back(d);
  }
  return list.is_empty_list() ? TemplateData(false) : TemplateData("rows", list);
}

TemplateData problem_data(const ResultsIndex& index, const ExtentFacts& f,
                          const std::vector<ParameterSeries>& all, const SeriesRefs& series) {
  const schema::ProblemRecord* record = index.problem(f.problem);
  TemplateData d;
  d.set("label", std::string(schema::label(f.problem)));
  d.set("description", record ? " — " + record->description : std::string());
  d.set("singular", index.singular(f.problem));
  d.set("exact", format_value(index.exact_of(*series.front()->points.front().row)));
  d.set("exact_source", record ? record->exact_source : std::string());
  d.set("series", series_table(index, series));
  d.set("splits", template_list(f.splits, [](const ErrorSplit& s) {
          TemplateData t;
          t.set("option", s.option);
          t.set("f_error", format_error_resolved(s.f_error));
          t.set("block", format_error_resolved(s.block));
          t.set("discretization", format_error_resolved(s.discretization));
          t.set("remaining", format_error_resolved(s.remaining));
          t.set("widest", format_parameter(s.widest));
          return t;
        }));
  const auto num = [](std::optional<double> v, const char* format = "{:g}") {
    return v ? TemplateData(fmt::format(fmt::runtime(format), *v)) : TemplateData(false);
  };
  d.set("half_space", num(f.half_space));
  d.set("change_after", num(f.change_after_half_space, "{:.3f}"));
  d.set("half_space_series", std::to_string(f.half_space_series));
  d.set("n_series", std::to_string(f.n_series));
  d.set("threshold", fmt::format("{:g}", kHalfSpaceChangePercent));
  d.set("second_widest", num(f.second_widest));
  d.set("widest", num(f.widest));
  d.set("last_change", num(f.last_change, "{:.3f}"));
  d.set("grades_extent", num(f.grades_extent));
  if (f.grades_extent) {
    const double k = *f.grades_extent;
    d.set("grades", pair_rows(
                        index, series, 1.0, [k](const auto& s) { return s.at(k); }, false));
  }
  d.set("gap_extent", num(f.gap_extent));
  if (f.gap_extent) {
    const double k = *f.gap_extent;
    const auto block_normal = [&](const ParameterSeries& s) {
      const ParameterSeries* twin = block_normal_of(all, s);
      return twin ? twin->at(k) : nullptr;
    };
    d.set("gap", pair_rows(index, series, k, block_normal, true));
  }
  return d;
}

/// The plain series of each problem that has some, in the report's problem order.
std::vector<std::pair<schema::ProblemId, SeriesRefs>> by_problem(
    const ResultsIndex& index, const std::vector<ParameterSeries>& all) {
  std::vector<std::pair<schema::ProblemId, SeriesRefs>> out;
  for (const schema::ProblemRecord* p : index.problems()) {
    const SeriesRefs series = select_series(all, [&](const ParameterSeries& s) {
      return s.spec.problem == p->id && s.spec.overrides.empty();
    });
    if (!series.empty())
      out.emplace_back(p->id, series);
  }
  return out;
}

}  // namespace

bool in_extent_study(const schema::CaseSpec& s) {
  const auto gap = s.overrides.find(kGapKey);
  const std::size_t n_overrides = gap == s.overrides.end() ? 1 : gap->second == 1.0 ? 2 : 0;
  return s.overrides.contains(kExtentKey) && s.overrides.size() == n_overrides &&
         s.solver == schema::SolverKind::builtin && s.target == schema::TargetKind::Discretized &&
         s.recovery == schema::Recovery::spr;
}

std::vector<ExtentFacts> extent_facts(const ResultsIndex& index) {
  const std::vector<ParameterSeries> all = collect_series(index);
  std::vector<ExtentFacts> out;
  for (const auto& [problem, series] : by_problem(index, all))
    out.push_back(facts_of(index, problem, all, series));
  return out;
}

std::string extent_section(const ResultsIndex& index) {
  const std::vector<ParameterSeries> all = collect_series(index);
  if (std::ranges::none_of(all, [](const ParameterSeries& s) { return s.spec.overrides.empty(); }))
    return {};
  TemplateData list{TemplateData::type::list};
  for (const auto& [problem, series] : by_problem(index, all))
    list.push_back(problem_data(index, facts_of(index, problem, all, series), all, series));
  TemplateData d("problems", list);
  d.set("marks_legend", evidence_marks_legend());
  return render_template(templates::extent_section, d);
}

}  // namespace cs::reports

#include "reports/findings/extent_section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

std::string series_table(const ResultsIndex& index,
                         const std::vector<const ExtentSeries*>& series) {
  MarkdownTable table({"Quantity", "Element", "Option", "extent", "C", "M", "F", "Richardson limit",
                       "F − limit", "change of F from the previous extent"});
  for (const ExtentSeries* s : series) {
    std::optional<double> previous;
    for (const auto& [k, row] : s->by_extent) {
      const auto exact = index.exact_of(*row);
      const auto lim = richardson(*row);
      std::vector<std::string> cells{std::string(schema::label(s->quantity)),
                                     std::string(schema::to_string(s->element)), s->option.label(),
                                     extent_label(k)};
      for (std::size_t m = 0; m < 3; ++m) {
        const auto v = row->values[m];
        cells.push_back(
            v ? fmt::format("{} ({})", format_value(*v), percent_cell(percent_of(v, exact)))
              : std::string(kMissing));
      }
      cells.push_back(
          lim ? fmt::format("{} ({})", format_value(*lim), percent_cell(percent_of(lim, exact)))
              : (row->estimate ? row->estimate->note : std::string(kMissing)));
      const auto f = fine_value(*row);
      cells.push_back(percent_cell(lim && f ? percent_of(f, lim) : std::nullopt));
      cells.push_back(percent_cell(previous && f ? percent_of(f, previous) : std::nullopt));
      previous = f;
      table.add_row(cells);
    }
  }
  return table.render();
}

/// How the error at the study's extent splits: the block (limit at 1 against the limit at the
/// largest extent), the discretization (F against the limit at 1), and what is left at the
/// largest extent (its limit against the exact value).
std::string error_split(const ResultsIndex& index, const std::vector<const ExtentSeries*>& series) {
  std::string out;
  for (const ExtentSeries* s : series) {
    if (s->by_extent.size() < 2 || !s->by_extent.contains(1.0))
      continue;
    const schema::RowVerdict& study = *s->by_extent.at(1.0);
    const auto& [k_max, widest] = *s->by_extent.rbegin();
    const auto exact = index.exact_of(study);
    const auto lim1 = richardson(study), lim_max = richardson(*widest), f1 = fine_value(study);
    if (!exact || !lim1 || !lim_max || !f1)
      continue;
    out += fmt::format(
        "- {} {} {}: F-mesh error at the study's extent {}; of it the block accounts for {} (the "
        "limit at extent 1 against the limit at {}), the discretization for {} (F against the "
        "limit at extent 1); at extent {} the limit is {} from the exact value.\n",
        schema::label(s->quantity), schema::to_string(s->element), s->option.label(),
        percent_cell(percent_of(f1, exact)), percent_cell(100.0 * (*lim1 - *lim_max) / *exact),
        extent_label(k_max), percent_cell(100.0 * (*f1 - *lim1) / *exact), extent_label(k_max),
        percent_cell(percent_of(lim_max, exact)));
  }
  return out;
}

/// "S, half-space": every option's grade at the half-space extent beside its grade at the study's
/// geometry, both against the physical exact value.
std::string half_space_grades(const ResultsIndex& index,
                              const std::vector<const ExtentSeries*>& series, double k) {
  MarkdownTable table({"Quantity", "Element", "Option", "study geometry (extent 1): F error",
                       "grade", fmt::format("half-space (extent {}): F error", extent_label(k)),
                       "grade"});
  for (const ExtentSeries* s : series) {
    const auto at = s->by_extent.find(k);
    const auto base = s->by_extent.find(1.0);
    if (at == s->by_extent.end() || base == s->by_extent.end())
      continue;
    const auto exact = index.exact_of(*base->second);
    table.add_row({std::string(schema::label(s->quantity)),
                   std::string(schema::to_string(s->element)), s->option.label(),
                   percent_cell(percent_of(fine_value(*base->second), exact)),
                   format_grade_cell(index, base->second),
                   percent_cell(percent_of(fine_value(*at->second), exact)),
                   format_grade_cell(index, at->second)});
  }
  return table.n_rows() == 0 ? std::string() : table.render();
}

/// The extent at which the half-space grades are given: of the extents at or beyond `from`, the
/// one with the most series (options), the widest among equals (every option is run at the
/// widest all-options extent, a few only further out).
double widest_extent_of_most_options(const std::vector<const ExtentSeries*>& series, double from) {
  double best = from;
  std::size_t most = 0;
  for (double k : extents_of(series)) {
    if (k < from)
      continue;
    const auto n = static_cast<std::size_t>(
        std::count_if(series.begin(), series.end(),
                      [k](const ExtentSeries* s) { return s->by_extent.contains(k); }));
    if (n >= most) {
      most = n;
      best = k;
    }
  }
  return best;
}

/// The widest extent at which some series has rows with both normals.
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

/// "C, M, F" errors of a row against the exact value, e.g. "+0.07, −0.11, −0.11 %".
std::string mesh_errors(const schema::RowVerdict& row, std::optional<double> exact) {
  std::vector<std::string> cells;
  for (std::size_t m = 0; m < 3; ++m)
    cells.push_back(percent_cell(percent_of(row.values[m], exact)));
  return fmt::format("{}", fmt::join(cells, ", "));
}

/// Every option at extent k graded twice: gaps along the target's normal (the default) and
/// along the block's own normal (`half_space_gap=1`), against the same exact value.
std::string gap_normal_part(const ResultsIndex& index, schema::ProblemId problem,
                            const std::vector<const ExtentSeries*>& series) {
  const auto k = widest_compared_extent(series);
  if (!k)
    return {};
  MarkdownTable table({"Quantity", "Element", "Option", "target's normal: C, M, F errors", "grade",
                       "block's normal: C, M, F errors", "grade"});
  for (const ExtentSeries* s : series) {
    const auto plain = s->by_extent.find(*k);
    const auto block = s->block_normal.find(*k);
    if (plain == s->by_extent.end() || block == s->block_normal.end())
      continue;
    const auto exact = index.exact_of(*plain->second);
    table.add_row({std::string(schema::label(s->quantity)),
                   std::string(schema::to_string(s->element)), s->option.label(),
                   mesh_errors(*plain->second, exact), format_grade_cell(index, plain->second),
                   mesh_errors(*block->second, exact), format_grade_cell(index, block->second)});
  }
  return fmt::format(
      "\n\"{0}, half-space gap\": at extent {1}, each option with its gaps measured along the "
      "target's normal (the default) and along the block's own normal (`--set "
      "half_space_gap=1`), the linearization of the half-space theory behind the exact value. On "
      "the punch's rounded edge the target's normal is tilted by up to (a − b)/r_e, so the "
      "default also sees that tilt times the block surface's tangential displacement, which "
      "points inwards under the punch and is proportional to (1 − 2ν)(1 + ν) p/E. That term is "
      "of first order in the load and absent from the small-strain theory: it is a floor that "
      "refinement does not remove. Both columns are graded against the same exact value.\n\n{2}",
      schema::label(problem), extent_label(*k), table.render());
}

std::string problem_part(const ResultsIndex& index, schema::ProblemId problem,
                         const std::vector<const ExtentSeries*>& series) {
  const schema::ProblemRecord* record = index.problem(problem);
  const auto exact = index.exact_of(*series.front()->by_extent.begin()->second);
  std::string out = fmt::format("### {}{}\n\n", schema::label(problem),
                                record != nullptr ? " — " + record->description : std::string());
  const bool singular = index.singular(problem);
  if (singular) {
    out +=
        "A singular problem: its peak grows without bound under refinement, so there is no "
        "limit to split; the table shows how the fine-mesh peak moves with the extent.\n\n";
  } else {
    out += fmt::format("Errors against the exact value {} ({}).\n\n", format_value(exact),
                       record != nullptr ? record->exact_source : std::string());
  }
  out += series_table(index, series) + "\n";
  if (!singular)
    out += error_split(index, series);
  const auto k = half_space_extent(series);
  const auto ks = extents_of(series);
  if (k) {
    out += fmt::format(
        "\nFrom extent {} on, no fine-mesh value changes by {} % or more ({} % at most): at this "
        "extent the block stands for a half-space.\n",
        extent_label(*k), kHalfSpaceChangePercent,
        fmt::format("{:.3f}",
                    largest_change_from(
                        series, ks,
                        static_cast<std::size_t>(std::find(ks.begin(), ks.end(), *k) - ks.begin()))
                        .value_or(0.0)));
    const double k_grades = widest_extent_of_most_options(series, *k);
    if (!singular) {
      const std::string grades = half_space_grades(index, series, k_grades);
      if (!grades.empty()) {
        out += fmt::format(
            "\n\"{}, half-space\": each option graded at extent {} (the widest extent run with "
            "the most options, at or beyond the half-space extent {}), against the same exact "
            "value as the study geometry beside it.\n\n{}",
            schema::label(problem), extent_label(k_grades), extent_label(*k), grades);
      }
    }
  } else if (ks.size() >= 2) {
    out += fmt::format(
        "\nBetween the two widest extents run, {} and {}, a fine-mesh value still changes by "
        "{} % (the criterion is below {} %): no extent run here stands for a half-space.\n",
        extent_label(ks[ks.size() - 2]), extent_label(ks.back()),
        fmt::format("{:.3f}", change_after(series, ks[ks.size() - 2]).value_or(0.0)),
        kHalfSpaceChangePercent);
  }
  if (!singular)
    out += gap_normal_part(index, problem, series);
  return out + "\n";
}

}  // namespace

bool in_extent_study(const schema::CaseSpec& s) {
  return in_plain_extent_study(s) || in_gap_study(s);
}

std::string extent_section(const ResultsIndex& index) {
  const std::vector<ExtentSeries> all = collect_series(index);
  if (all.empty())
    return {};
  std::string parts;
  for (const schema::ProblemRecord* p : index.problems()) {
    std::vector<const ExtentSeries*> series;
    for (const auto& s : all) {
      if (s.problem == p->id)
        series.push_back(&s);
    }
    if (!series.empty())
      parts += problem_part(index, p->id, series);
  }
  return "## The block's extent: finite block or half-space\n\n"
         "The study's blocks are finite (8b deep on rollers for the Steuermann problems); the "
         "exact solutions are for a half-space. Here the same problems are run with the block "
         "enlarged (`--set extent=K`: width and depth K times the study's, the mesh within half "
         "the study's extent unchanged and the rest stretched outwards). Each cell: our value "
         "(its % error). The Richardson limit of C, M, F (when the three are in the asymptotic "
         "range) removes the discretization error, so its change with the extent is the "
         "block's part of the error.\n\n" +
         parts;
}

}  // namespace cs::reports

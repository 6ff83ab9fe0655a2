#include "reports/findings/sweep_section.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/figures/sweep_figure.hpp"
#include "reports/findings/sweep_series.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::Grade;
using schema::Quantity;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string values_text(const std::vector<double>& values) {
  if (values.empty())
    return "none";
  std::string out;
  for (double v : values)
    out += (out.empty() ? "" : ", ") + format_swept_value(v);
  return out;
}

/// "1e-3 to 1e4" when `chosen` is a contiguous run of `all`, else the list.
std::string window_text(const std::vector<double>& chosen, const std::vector<double>& all) {
  if (chosen.size() < 2)
    return values_text(chosen);
  const auto first = std::find(all.begin(), all.end(), chosen.front());
  const bool contiguous = first != all.end() && all.end() - first >= std::ssize(chosen) &&
                          std::equal(chosen.begin(), chosen.end(), first);
  return contiguous ? fmt::format("{} to {}", format_swept_value(chosen.front()),
                                  format_swept_value(chosen.back()))
                    : values_text(chosen);
}

std::string series_label(const SweepSeries& s, Quantity q) {
  return fmt::format("{} {} {} {} {}", schema::to_string(s.base.problem), schema::to_string(q),
                     schema::to_string(s.base.mesh), schema::to_string(s.base.element),
                     s.option_label());
}

const schema::QuantityResult* quantity_at(const SweepPoint& p, Quantity q) {
  for (const auto& r : p.result->quantities) {
    if (r.quantity == q)
      return &r;
  }
  return nullptr;
}

/// Every (series, quantity) pair of a key, optionally filtered by the series.
struct Curve {
  const SweepSeries* series;
  Quantity quantity;
};

std::vector<Curve> curves(const std::vector<SweepSeries>& series,
                          const std::function<bool(const SweepSeries&)>& keep) {
  std::vector<Curve> out;
  for (const auto& s : series) {
    if (s.points.empty() || (keep && !keep(s)))
      continue;
    for (const auto& q : s.points.front().result->quantities)
      out.push_back({&s, q.quantity});
  }
  return out;
}

bool penalty_based(const SweepSeries& s) {
  return schema::traits(s.base.algorithm).penalty_based;
}

/// The swept values at which every curve satisfies `ok` (a value a curve lacks fails it).
std::vector<double> values_where_all(const std::vector<Curve>& cs, const std::vector<double>& all,
                                     const std::function<bool(const SweepPoint&, Quantity)>& ok) {
  std::vector<double> out;
  for (double v : all) {
    bool every = !cs.empty();
    for (const auto& c : cs) {
      const auto it = std::find_if(c.series->points.begin(), c.series->points.end(),
                                   [v](const SweepPoint& p) { return p.value == v; });
      every = every && it != c.series->points.end() && ok(*it, c.quantity);
    }
    if (every)
      out.push_back(v);
  }
  return out;
}

bool graded_at_most(const SweepPoint& p, Quantity q, Grade worst) {
  const auto* r = quantity_at(p, q);
  return SweepSeries::converged(p) && r != nullptr && std::isfinite(r->error_percent) &&
         static_cast<int>(r->grade) <= static_cast<int>(worst);
}

/// The table of a key: one row per curve, one column per value: error, grade, iterations.
std::string key_table(const std::vector<SweepSeries>& series, const std::vector<double>& values) {
  std::vector<std::string> header{"Problem", "Quantity", "Mesh", "Element", "Option"};
  for (double v : values)
    header.push_back(format_swept_value(v));
  MarkdownTable table(header);
  const auto finest = [&](const SweepSeries& s) { return on_finest_mesh(s, series); };
  for (const auto& c : curves(series, finest)) {
    const SweepSeries& s = *c.series;
    std::vector<std::string> row{std::string(schema::to_string(s.base.problem)),
                                 std::string(schema::to_string(c.quantity)),
                                 std::string(schema::to_string(s.base.mesh)),
                                 std::string(schema::to_string(s.base.element)), s.option_label()};
    for (double v : values) {
      const auto it = std::find_if(s.points.begin(), s.points.end(),
                                   [v](const SweepPoint& p) { return p.value == v; });
      const auto* q = it == s.points.end() ? nullptr : quantity_at(*it, c.quantity);
      if (q == nullptr || !std::isfinite(q->error_percent)) {
        row.push_back(it == s.points.end() ? kMissing : std::string(to_string(it->result->status)));
        continue;
      }
      row.push_back(fmt::format("{} {}, {} it{}", format_percent(q->error_percent),
                                schema::to_string(q->grade), it->result->iterations,
                                SweepSeries::converged(*it) ? "" : " (not converged)"));
    }
    table.add_row(std::move(row));
  }
  return table.render();
}

std::string figure_link(const FigureSet& figures, const std::string& key) {
  for (const auto& f : figures.figures) {
    if (f.file != sweep_figure_file(key))
      continue;
    std::string notes;
    for (const auto& n : f.notes)
      notes += fmt::format("*Note: {}*\n\n", n);
    if (f.produced)
      return fmt::format("![{}]({})\n\n*{}*\n\n{}", f.caption_md, f.file, f.caption_md, notes);
    return fmt::format("(The figure of {} could not be drawn: {}.)\n\n", key, f.error);
  }
  if (!figures.unavailable.empty())
    return fmt::format("(No figure: {}.)\n\n", figures.unavailable);
  return "";
}

/// The largest spread (max - min, percentage points) of the error over the values, per curve,
/// and the curve that has it.
std::pair<double, const Curve*> largest_spread(const std::vector<Curve>& cs) {
  double worst = -1;
  const Curve* at = nullptr;
  for (const auto& c : cs) {
    double lo = kInf, hi = -kInf;
    for (const auto& p : c.series->points) {
      if (const auto e = SweepSeries::error(p, c.quantity); e && SweepSeries::converged(p)) {
        lo = std::min(lo, *e);
        hi = std::max(hi, *e);
      }
    }
    if (hi >= lo && hi - lo > worst) {
      worst = hi - lo;
      at = &c;
    }
  }
  return {worst, at};
}

std::string spread_answer(const std::vector<Curve>& cs, const std::string& key,
                          const std::vector<double>& values) {
  const auto [spread, at] = largest_spread(cs);
  if (at == nullptr)
    return fmt::format("- No converged case has an error to compare over {}.\n", key);
  return fmt::format(
      "- Over {} = {}, the largest change of an error is {:.3g} percentage points ({}); {}.\n", key,
      window_text(values, values), spread, series_label(*at->series, at->quantity),
      spread <= kSamePoints ? "it changes nothing"
                            : fmt::format("below {} points it changes nothing", kSamePoints));
}

int count_not_converged(const std::vector<SweepSeries>& series, double v,
                        const std::function<bool(const SweepSeries&)>& keep) {
  int n = 0;
  for (const auto& s : series) {
    if (!keep(s))
      continue;
    for (const auto& p : s.points)
      n += p.value == v && !SweepSeries::converged(p) ? 1 : 0;
  }
  return n;
}

/// The most iterations of the cases of one algorithm at a value, or -1.
int most_iterations(const std::vector<SweepSeries>& series, double v, Algorithm a) {
  int most = -1;
  for (const auto& s : series) {
    if (s.base.algorithm != a)
      continue;
    for (const auto& p : s.points) {
      if (p.value == v)
        most = std::max(most, p.result->iterations);
    }
  }
  return most;
}

std::string iterations_table(const std::vector<SweepSeries>& series,
                             const std::vector<double>& values) {
  std::vector<std::string> header{"Algorithm"};
  for (double v : values)
    header.push_back(format_swept_value(v));
  MarkdownTable table(header);
  for (const auto a : schema::values<Algorithm>()) {
    if (most_iterations(series, values.front(), a) < 0)
      continue;
    std::vector<std::string> row{std::string(schema::to_string(a))};
    for (double v : values) {
      const int it = most_iterations(series, v, a);
      const int nc = count_not_converged(
          series, v, [a](const SweepSeries& s) { return s.base.algorithm == a; });
      row.push_back(it < 0 ? kMissing
                           : fmt::format("{}{}", it, nc > 0 ? fmt::format(" ({} n.c.)", nc) : ""));
    }
    table.add_row(std::move(row));
  }
  return "Most iterations of any swept case per algorithm (n.c.: cases not converged):\n\n" +
         table.render() + "\n";
}

/// AL against PM: the largest |e_AL - e_PM| at each value over the pairs of series that differ
/// only in the algorithm.
std::string al_pm_answer(const std::vector<SweepSeries>& series,
                         const std::vector<double>& values) {
  std::map<double, double> gap;
  std::map<double, bool> iterations_differ;
  bool any_pair = false;
  for (const auto& al : series) {
    if (al.base.algorithm != Algorithm::AL)
      continue;
    schema::CaseSpec pm_spec = al.base;
    pm_spec.algorithm = Algorithm::PM;
    const auto pm = std::find_if(series.begin(), series.end(), [&](const SweepSeries& s) {
      return schema::case_id(s.base) == schema::case_id(pm_spec);
    });
    if (pm == series.end())
      continue;
    any_pair = true;
    for (const auto& a : al.points) {
      for (const auto& p : pm->points) {
        if (p.value != a.value)
          continue;
        for (const auto& q : a.result->quantities) {
          const auto ea = SweepSeries::error(a, q.quantity);
          const auto ep = SweepSeries::error(p, q.quantity);
          if (ea && ep)
            gap[a.value] = std::max(gap[a.value], std::abs(*ea - *ep));
        }
        iterations_differ[a.value] =
            iterations_differ[a.value] || a.result->iterations != p.result->iterations;
      }
    }
  }
  if (!any_pair)
    return "";
  std::vector<double> apart, same;
  double widest = 0, widest_at = 0;
  for (double v : values) {
    if (!gap.contains(v))
      continue;
    (gap[v] > kSamePoints ? apart : same).push_back(v);
    if (gap[v] > widest) {
      widest = gap[v];
      widest_at = v;
    }
  }
  if (apart.empty())
    return fmt::format(
        "- AL and PM do not separate: at every FKN swept their errors agree to {} percentage "
        "points (the penetration never exceeds FTOLN, so AL never augments).\n",
        kSamePoints);
  std::vector<double> it_apart;
  for (double v : values) {
    if (iterations_differ[v])
      it_apart.push_back(v);
  }
  return fmt::format(
      "- AL and PM separate at FKN = {} (by up to {:.3g} percentage points, at FKN = {}), where "
      "the penetration exceeds FTOLN and AL augments (their iteration counts differ at FKN = "
      "{}); they agree to {} points at FKN = {}.\n",
      values_text(apart), widest, format_swept_value(widest_at), values_text(it_apart), kSamePoints,
      values_text(same));
}

/// Can any FKN reproduce the study's AL error on S(1/3) (sigma_c, Q4, ss, mesh F)?
std::string study_al_answer(const std::vector<SweepSeries>& series, const StudyReference& study) {
  const auto match =
      study.find_value(schema::ProblemId::S_1_3, Quantity::sigma_c, schema::Element::Q4,
                       Algorithm::AL, schema::ContactKind::ss, schema::MeshLevel::F);
  if (match.value == nullptr || !match.value->exact)
    return "";
  const double target = grading::error_percent(match.value->value, *match.value->exact);
  std::string out;
  for (const auto& s : series) {
    if (s.base.problem != schema::ProblemId::S_1_3 || s.base.algorithm != Algorithm::AL ||
        s.base.element != schema::Element::Q4 || s.base.contact != schema::ContactKind::ss ||
        s.base.mesh != schema::MeshLevel::F || !s.base.overrides.empty())
      continue;
    std::vector<std::string> crossings;
    double lo = kInf, hi = -kInf;
    const SweepPoint* prev = nullptr;
    for (const auto& p : s.points) {
      const auto e = SweepSeries::error(p, Quantity::sigma_c);
      if (!e || !SweepSeries::converged(p))
        continue;
      lo = std::min(lo, *e);
      hi = std::max(hi, *e);
      if (prev != nullptr) {
        const double ep = *SweepSeries::error(*prev, Quantity::sigma_c);
        if ((ep - target) * (*e - target) <= 0 && ep != *e) {
          // Interpolated in log FKN: the errors change with the order of magnitude of FKN.
          const double t = (target - ep) / (*e - ep);
          const double x =
              std::exp(std::log(prev->value) + t * (std::log(p.value) - std::log(prev->value)));
          crossings.push_back(fmt::format("{:.2g}", x));
        }
      }
      prev = &p;
    }
    if (hi < lo)
      continue;
    out += fmt::format(
        "- The study's AL error on S(1/3) (σ̄<sub>c</sub>, 4Q, ss, mesh F: {} against {}: {}) "
        "{}: our AL ss Q4 error ranges from {} to {} over the FKN swept.\n",
        match.value->printed, match.value->exact_printed, format_percent(target),
        crossings.empty() ? "is reproduced by no swept FKN"
                          : fmt::format("is reproduced near FKN = {} (interpolated in log FKN)",
                                        fmt::join(crossings, ", ")),
        format_percent(lo), format_percent(hi));
  }
  return out;
}

std::string fkn_answers(const ResultsIndex& index, const std::vector<SweepSeries>& series,
                        const std::vector<double>& values, const StudyReference& study) {
  const auto keep = [&](const SweepSeries& s) {
    return penalty_based(s) && on_finest_mesh(s, series);
  };
  // The stress rows: the contact half-width is graded apart (it moves by whole nodes).
  auto cs = curves(series, keep);
  std::erase_if(cs, [](const Curve& c) { return c.quantity == Quantity::contact_half_width; });
  if (cs.empty())
    return "- No AL or PM case was swept.\n";
  std::string out;
  const auto e = values_where_all(
      cs, values, [](const SweepPoint& p, Quantity q) { return graded_at_most(p, q, Grade::e); });
  const auto eg = values_where_all(
      cs, values, [](const SweepPoint& p, Quantity q) { return graded_at_most(p, q, Grade::g); });
  out += fmt::format(
      "- Every swept AL/PM stress row ({} of them, on the finest mesh swept; the contact "
      "half-width is graded apart) is e at FKN = {}, and e or g at FKN = {}.\n",
      cs.size(), window_text(e, values), window_text(eg, values));
  for (const auto& c : cs) {
    const auto own = values_where_all({c}, values, [](const SweepPoint& p, Quantity q) {
      return graded_at_most(p, q, Grade::e);
    });
    if (own.empty()) {
      out += fmt::format("  - {} is e at no swept FKN.\n", series_label(*c.series, c.quantity));
    }
  }
  // c: from the rows of the swept option sets (those run on C, M and F).
  std::map<std::string, const schema::RowVerdict*> rows;
  for (const auto& r : index.results().rows)
    rows[r.id] = &r;
  std::vector<double> converging;
  bool any_row = false;
  for (double v : values) {
    bool every = true, some = false;
    for (const auto& c : cs) {
      schema::CaseSpec spec = c.series->base;
      spec.overrides["fkn"] = v;
      const auto it =
          rows.find(schema::case_key(spec) + "/" + std::string(schema::to_string(c.quantity)));
      if (it == rows.end() || !ResultsIndex::complete(*it->second))
        continue;
      some = true;
      every = every && it->second->converging.value_or(false);
    }
    any_row = any_row || some;
    if (some && every)
      converging.push_back(v);
  }
  out += any_row ? fmt::format(
                       "- Of the rows swept on C, M and F, every one converges (c) at "
                       "FKN = {}.\n",
                       window_text(converging, values))
                 : "- Convergence (c) needs the C, M and F meshes: no swept row has all three.\n";
  // Iterations, the cases that do not converge, and the range of a default.
  std::vector<std::string> not_converged;
  for (double v : values) {
    if (const int n = count_not_converged(series, v, penalty_based); n > 0)
      not_converged.push_back(fmt::format("{} at FKN = {}", n, format_swept_value(v)));
  }
  out += fmt::format(
      "- AL iterations (most of any swept case) go from {} at FKN = {} to {} at FKN = {}; {}.\n",
      most_iterations(series, values.front(), Algorithm::AL), format_swept_value(values.front()),
      most_iterations(series, values.back(), Algorithm::AL), format_swept_value(values.back()),
      not_converged.empty()
          ? std::string("every AL/PM case converges")
          : fmt::format("AL/PM cases that do not converge: {}", fmt::join(not_converged, ", ")));
  if (!eg.empty()) {
    const double lo = eg.front();
    const int lmp = most_iterations(series, lo, Algorithm::LMP);
    std::optional<double> first_nc_above;
    for (double v : values) {
      if (v > lo && !first_nc_above && count_not_converged(series, v, penalty_based) > 0)
        first_nc_above = v;
    }
    out += fmt::format(
        "- A default FKN: the smallest swept FKN at which every swept AL/PM row is e or g is {}; "
        "there AL takes at most {} iterations{}{}. The default is the smallest such FKN: larger "
        "ones buy accuracy only on rows already e or g, cost iterations and approach the "
        "ill-conditioning{}.\n",
        format_swept_value(lo), most_iterations(series, lo, Algorithm::AL),
        lmp >= 0 ? fmt::format(" (LMP, which enforces contact exactly, {})", lmp) : "",
        e.empty() ? ""
                  : fmt::format("; every row is e from FKN = {}", format_swept_value(e.front())),
        first_nc_above ? fmt::format(" (a case stops converging at FKN = {})",
                                     format_swept_value(*first_nc_above))
                       : "");
  }
  out += al_pm_answer(series, values);
  out += study_al_answer(series, study);
  return out + "\n" + iterations_table(series, values);
}

std::string pinball_answers(const std::vector<SweepSeries>& series,
                            const std::vector<double>& values) {
  std::string out;
  for (const auto& c : curves(series, [&series](const SweepSeries& s) {
         return s.base.algorithm == Algorithm::MPC && on_finest_mesh(s, series);
       })) {
    if (c.quantity == Quantity::contact_half_width)
      continue;  // graded apart
    std::vector<double> failed;
    std::vector<std::string> cells;
    for (const auto& p : c.series->points) {
      const auto e = SweepSeries::error(p, c.quantity);
      if (!SweepSeries::converged(p) || !e)
        failed.push_back(p.value);
      else
        cells.push_back(fmt::format("{} at {}", format_percent(*e), format_swept_value(p.value)));
    }
    out += fmt::format("- {}: {}{}.\n", series_label(*c.series, c.quantity),
                       cells.empty() ? std::string("no converged case")
                                     : fmt::format("{}", fmt::join(cells, ", ")),
                       failed.empty() ? ""
                                      : fmt::format("; not converged or failed at pinball = {}",
                                                    values_text(failed)));
  }
  if (out.empty())
    return "- No MPC case was swept: MPC is the algorithm the pinball decides (it ties every "
           "point within it).\n" +
           spread_answer(curves(series, nullptr), "pinball", values);
  return "- MPC ties every point within the pinball at the start: its error at each pinball "
         "swept (the others' contact search only):\n" +
         out;
}

std::string e_ratio_answers(const std::vector<SweepSeries>& series) {
  std::string out;
  double latest = 0;
  for (const auto& c : curves(series, nullptr)) {
    const auto& pts = c.series->points;
    const auto last = SweepSeries::error(pts.back(), c.quantity);
    if (!last || c.quantity == Quantity::contact_half_width)
      continue;
    double settled = pts.back().value;
    for (auto it = pts.rbegin(); it != pts.rend(); ++it) {
      const auto e = SweepSeries::error(*it, c.quantity);
      if (!e || std::abs(*e - *last) > kSettledPoints)
        break;
      settled = it->value;
    }
    latest = std::max(latest, settled);
    out += fmt::format("  - {}: from E ratio {} on ({} at {}).\n",
                       series_label(*c.series, c.quantity), format_swept_value(settled),
                       format_percent(*last), format_swept_value(pts.back().value));
  }
  if (out.empty())
    return "- No swept case has an error.\n";
  const double smallest = swept_values(series).front();
  return fmt::format(
             "- The stiff-indenter model stops mattering (every stress error within {} "
             "percentage points of its value at the largest ratio swept) from E ratio {} on{}, "
             "for every row swept:\n",
             kSettledPoints, format_swept_value(latest),
             latest == smallest ? " (already at the smallest ratio swept)" : "") +
         out;
}

std::string key_title(const std::string& key) {
  if (key == "fkn")
    return "FKN, the normal penalty stiffness";
  if (key == "ftoln")
    return "FTOLN, the penetration tolerance";
  if (key == "pinball")
    return "Pinball region";
  if (key == "E_ratio")
    return "E ratio, indenter over indented body";
  if (key == "p_over_E")
    return "Load p/E";
  return key;
}

std::string key_answers(const ResultsIndex& index, const std::string& key,
                        const std::vector<SweepSeries>& series, const std::vector<double>& values,
                        const StudyReference& study) {
  if (key == "fkn")
    return fkn_answers(index, series, values, study);
  if (key == "pinball")
    return pinball_answers(series, values);
  if (key == "E_ratio")
    return e_ratio_answers(series);
  if (key == "ftoln") {
    const auto al =
        curves(series, [](const SweepSeries& s) { return s.base.algorithm == Algorithm::AL; });
    return spread_answer(al.empty() ? curves(series, nullptr) : al, "FTOLN", values);
  }
  if (key == "p_over_E")
    return spread_answer(curves(series, nullptr), "p/E", values) +
           "- The normalized results of this small-strain model must not depend on the load: "
           "a change above the round-off would be a defect.\n";
  return spread_answer(curves(series, nullptr), key, values);
}

}  // namespace

std::string sweep_section(const ResultsIndex& index, const StudyReference& study,
                          const FigureSet& figures) {
  const auto& doc = index.results();
  std::string body;
  for (const auto& key : swept_keys(doc)) {
    const auto series = sweep_series(doc, key);
    const auto values = swept_values(series);
    if (values.empty())
      continue;
    body += fmt::format("### {} ({})\n\n{} values swept: {}; {} option sets.\n\n", key_title(key),
                        key, values.size(), values_text(values), series.size());
    body += key_answers(index, key, series, values, study) + "\n";
    body += figure_link(figures, key);
    body +=
        "Error (%), grade and iterations per swept value:\n\n" + key_table(series, values) + "\n";
  }
  if (body.empty())
    return "";
  return "## Parameter sweeps\n\nThe study used ANSYS's defaults for FKN, FTOLN and the pinball "
         "and offered \"no commentary on the possible improvements these other options might "
         "offer\". Here each swept parameter's effect on the error, computed from the swept "
         "cases of this results file (`run --sweep`).\n\n" +
         body;
}

}  // namespace cs::reports

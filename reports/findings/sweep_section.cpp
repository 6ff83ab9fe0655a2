#include "reports/findings/sweep_section.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/accuracy.hpp"
#include "reports/figures/sweep_figure.hpp"
#include "reports/findings/sweep_series.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::Grade;
using schema::Quantity;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string values_text(const std::vector<double>& values) {
  std::vector<std::string> parts;
  for (double v : values)
    parts.push_back(format_swept_value(v));
  return parts.empty() ? "none" : fmt::format("{}", fmt::join(parts, ", "));
}

/// "1e-3 to 1e4" when `chosen` is a contiguous run of `all`, else the list.
std::string window_text(const std::vector<double>& chosen, const std::vector<double>& all) {
  const auto first = chosen.empty() ? all.end() : std::find(all.begin(), all.end(), chosen.front());
  const bool contiguous = chosen.size() >= 2 && all.end() - first >= std::ssize(chosen) &&
                          std::equal(chosen.begin(), chosen.end(), first);
  return contiguous ? fmt::format("{} to {}", format_swept_value(chosen.front()),
                                  format_swept_value(chosen.back()))
                    : values_text(chosen);
}

/// One quantity of one series.
struct Curve {
  const SweepSeries* series;
  Quantity quantity;
  std::string label() const {
    const auto& b = series->base;
    return fmt::format("{} {} {} {} {}", schema::to_string(b.problem), schema::to_string(quantity),
                       schema::to_string(b.mesh), schema::to_string(b.element),
                       series->option_label());
  }
};

using Keep = std::function<bool(const SweepSeries&)>;

/// Every (series, quantity) pair the kept series have; the contact half-width (it moves by
/// whole nodes) is left out where `stresses_only`.
std::vector<Curve> curves(const std::vector<SweepSeries>& series, const Keep& keep,
                          bool stresses_only = false) {
  std::vector<Curve> out;
  for (const auto& s : series) {
    if (s.points.empty() || (keep && !keep(s)))
      continue;
    for (const auto& q : s.points.front().result->quantities) {
      if (!stresses_only || q.quantity != Quantity::contact_half_width)
        out.push_back({&s, q.quantity});
    }
  }
  return out;
}

const SweepPoint* point_at(const SweepSeries& s, double v) {
  const auto it = std::find_if(s.points.begin(), s.points.end(),
                               [v](const SweepPoint& p) { return p.value == v; });
  return it == s.points.end() ? nullptr : &*it;
}

bool graded_at_most(const SweepPoint* p, Quantity q, Grade worst) {
  const auto e = p ? SweepSeries::error(*p, q) : std::nullopt;
  return e && SweepSeries::converged(*p) && !schema::is_worse(grading::grade_of_error(*e), worst);
}

/// The swept values at which every curve is graded `worst` or better (converged).
std::vector<double> values_where_all(const std::vector<Curve>& cs, const std::vector<double>& all,
                                     Grade worst) {
  std::vector<double> out;
  for (double v : all) {
    if (!cs.empty() && std::all_of(cs.begin(), cs.end(), [&](const Curve& c) {
          return graded_at_most(point_at(*c.series, v), c.quantity, worst);
        }))
      out.push_back(v);
  }
  return out;
}

int count_not_converged(const std::vector<SweepSeries>& series, double v, const Keep& keep) {
  int n = 0;
  for (const auto& s : series) {
    const SweepPoint* p = keep(s) ? point_at(s, v) : nullptr;
    n += p && !SweepSeries::converged(*p) ? 1 : 0;
  }
  return n;
}

/// The most iterations of the cases of one algorithm at a value, or -1.
int most_iterations(const std::vector<SweepSeries>& series, double v, Algorithm a) {
  int most = -1;
  for (const auto& s : series) {
    if (const SweepPoint* p = s.base.algorithm == a ? point_at(s, v) : nullptr)
      most = std::max(most, p->result->iterations);
  }
  return most;
}

bool penalty_based(const SweepSeries& s) {
  return schema::traits(s.base.algorithm).penalty_based;
}

/// A table whose first columns are `header` (aligned as `align`), then one right-aligned
/// column per swept value.
MarkdownTable value_table(std::vector<std::string> header, std::vector<Align> align,
                          const std::vector<double>& values) {
  for (double v : values) {
    header.push_back(format_swept_value(v));
    align.push_back(Align::right);
  }
  return MarkdownTable(std::move(header), std::move(align));
}

/// One key's table: per curve on the finest mesh swept, per value the signed error, grade and
/// iterations, or the status of a case without an error.
std::string error_table(const std::vector<SweepSeries>& series, const std::vector<double>& values) {
  constexpr Align l = Align::left, c = Align::center;
  MarkdownTable t =
      value_table({"Problem", "Quantity", "Mesh", "Element", "Option"}, {l, l, c, c, l}, values);
  for (const Curve& curve :
       curves(series, [&](const SweepSeries& s) { return on_finest_mesh(s, series); })) {
    const auto& b = curve.series->base;
    std::vector<std::string> row{
        std::string(schema::to_string(b.problem)), std::string(schema::to_string(curve.quantity)),
        std::string(schema::to_string(b.mesh)), std::string(schema::to_string(b.element)),
        curve.series->option_label()};
    for (double v : values) {
      const SweepPoint* p = point_at(*curve.series, v);
      const auto e = p ? SweepSeries::error(*p, curve.quantity) : std::nullopt;
      row.push_back(!e ? (p ? std::string(to_string(p->result->status)) : kMissing)
                       : fmt::format("{} {}, {} it{}", format_error_resolved(*e),
                                     schema::to_string(grading::grade_of_error(*e)),
                                     p->result->iterations,
                                     SweepSeries::converged(*p) ? "" : " (not converged)"));
    }
    t.add_row(std::move(row));
  }
  return t.render();
}

/// The largest spread (max - min, percentage points) of a curve's converged errors.
TemplateData spread(const std::vector<Curve>& cs, const std::string& key,
                    const std::vector<double>& values) {
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
  TemplateData d;
  d.set("key", key);
  d.set("has_spread", at != nullptr);
  d.set("values", window_text(values, values));
  d.set("spread", fmt::format("{:.3g}", worst));
  d.set("curve", at ? at->label() : std::string());
  d.set("nothing", worst <= kSamePoints);
  d.set("same_points", fmt::format("{:g}", kSamePoints));
  return d;
}

/// AL against PM: the largest |e_AL - e_PM| per value over the series pairs that differ only in
/// the algorithm, and whether their iteration counts differ.
TemplateData al_pm(const std::vector<SweepSeries>& series, const std::vector<double>& values) {
  std::map<double, double> gap;
  std::map<double, bool> iterations_differ;
  for (const auto& al : series) {
    schema::CaseSpec pm_spec = al.base;
    pm_spec.algorithm = Algorithm::PM;
    const auto pm = std::find_if(series.begin(), series.end(), [&](const SweepSeries& s) {
      return schema::case_id(s.base) == schema::case_id(pm_spec);
    });
    if (al.base.algorithm != Algorithm::AL || pm == series.end())
      continue;
    for (const auto& a : al.points) {
      const SweepPoint* p = point_at(*pm, a.value);
      for (const auto& q : p ? a.result->quantities : std::vector<schema::QuantityResult>{}) {
        const auto ea = SweepSeries::error(a, q.quantity), ep = SweepSeries::error(*p, q.quantity);
        if (ea && ep)
          gap[a.value] = std::max(gap[a.value], std::abs(*ea - *ep));
      }
      iterations_differ[a.value] |= p && a.result->iterations != p->result->iterations;
    }
  }
  std::vector<double> apart, same, it_apart;
  double widest = 0, widest_at = 0;
  for (const auto& [v, g] : gap) {
    (g > kSamePoints ? apart : same).push_back(v);
    if (g > widest)
      std::tie(widest, widest_at) = std::make_pair(g, v);
  }
  for (double v : values) {
    if (iterations_differ[v])
      it_apart.push_back(v);
  }
  TemplateData d;
  d.set("same_points", fmt::format("{:g}", kSamePoints));
  d.set("separate", !apart.empty());
  d.set("apart", values_text(apart));
  d.set("widest", fmt::format("{:.3g}", widest));
  d.set("widest_at", format_swept_value(widest_at));
  d.set("it_apart", values_text(it_apart));
  d.set("same", values_text(same));
  return gap.empty() ? TemplateData(false) : d;
}

/// Can any FKN reproduce the study's AL error on S(1/3) (sigma_c, Q4, ss, mesh F)? A crossing is
/// interpolated in log FKN: the errors change with the order of magnitude of FKN.
TemplateData study_al(const std::vector<SweepSeries>& series, const schema::StudyReference& study) {
  const auto match =
      study.find_value(schema::ProblemId::S_1_3, Quantity::sigma_c, schema::Element::Q4,
                       Algorithm::AL, schema::ContactKind::ss, schema::MeshLevel::F);
  if (match.value == nullptr || !match.value->exact)
    return TemplateData(false);
  const double target = grading::error_percent(match.value->value, *match.value->exact);
  TemplateData list{TemplateData::type::list};
  for (const auto& s : series) {
    const auto& b = s.base;
    if (b.problem != schema::ProblemId::S_1_3 || b.algorithm != Algorithm::AL ||
        b.element != schema::Element::Q4 || b.contact != schema::ContactKind::ss ||
        b.mesh != schema::MeshLevel::F || !b.overrides.empty())
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
      const double ep = prev ? *SweepSeries::error(*prev, Quantity::sigma_c) : *e;
      if (prev && (ep - target) * (*e - target) <= 0 && ep != *e) {
        const double t = (target - ep) / (*e - ep);
        crossings.push_back(fmt::format(
            "{:.2g}", std::exp(std::log(prev->value) + t * std::log(p.value / prev->value))));
      }
      prev = &p;
    }
    if (hi < lo)
      continue;
    TemplateData d;
    d.set("printed", match.value->printed);
    d.set("exact", match.value->exact_printed);
    d.set("target", format_percent(target));
    d.set("reproduced", !crossings.empty());
    d.set("crossings", fmt::format("{}", fmt::join(crossings, ", ")));
    d.set("lo", format_percent(lo));
    d.set("hi", format_percent(hi));
    list.push_back(d);
  }
  return list;
}

/// Whether every swept AL/PM row run on C, M and F converges (the study's c), per value.
TemplateData fkn_convergence(const ResultsIndex& index, const std::vector<Curve>& cs,
                             const std::vector<double>& values) {
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
  return any_row ? TemplateData("window", window_text(converging, values)) : TemplateData(false);
}

TemplateData fkn(const ResultsIndex& index, const std::vector<SweepSeries>& series,
                 const std::vector<double>& values, const schema::StudyReference& study) {
  const auto cs = curves(
      series, [&](const SweepSeries& s) { return penalty_based(s) && on_finest_mesh(s, series); },
      true);
  TemplateData d;
  d.set("any", !cs.empty());
  if (cs.empty())
    return d;
  const auto e = values_where_all(cs, values, Grade::e);
  const auto eg = values_where_all(cs, values, Grade::g);
  d.set("n_rows", std::to_string(cs.size()));
  d.set("e", window_text(e, values));
  d.set("eg", window_text(eg, values));
  std::vector<Curve> never;
  std::copy_if(cs.begin(), cs.end(), std::back_inserter(never),
               [&](const Curve& c) { return values_where_all({c}, values, Grade::e).empty(); });
  d.set("never_e",
        template_list(never, [](const Curve& c) { return TemplateData("row", c.label()); }));
  d.set("convergence", fkn_convergence(index, cs, values));
  std::vector<std::string> not_converged;
  for (double v : values) {
    if (const int n = count_not_converged(series, v, penalty_based); n > 0)
      not_converged.push_back(fmt::format("{} at FKN = {}", n, format_swept_value(v)));
  }
  d.set("it_first", std::to_string(most_iterations(series, values.front(), Algorithm::AL)));
  d.set("v_first", format_swept_value(values.front()));
  d.set("it_last", std::to_string(most_iterations(series, values.back(), Algorithm::AL)));
  d.set("v_last", format_swept_value(values.back()));
  d.set("all_converge", not_converged.empty());
  d.set("not_converged", fmt::format("{}", fmt::join(not_converged, ", ")));
  if (!eg.empty()) {
    TemplateData def;
    const double lo = eg.front();
    def.set("fkn", format_swept_value(lo));
    def.set("al_it", std::to_string(most_iterations(series, lo, Algorithm::AL)));
    const int lmp = most_iterations(series, lo, Algorithm::LMP);
    def.set("has_lmp", lmp >= 0);
    def.set("lmp_it", std::to_string(lmp));
    def.set("has_e", !e.empty());
    def.set("e_from", e.empty() ? std::string() : format_swept_value(e.front()));
    const auto nc = std::find_if(values.begin(), values.end(), [&](double v) {
      return v > lo && count_not_converged(series, v, penalty_based) > 0;
    });
    def.set("has_nc", nc != values.end());
    def.set("nc_at", nc != values.end() ? format_swept_value(*nc) : std::string());
    d.set("default", def);
  }
  d.set("al_pm", al_pm(series, values));
  d.set("study_al", study_al(series, study));
  MarkdownTable iterations = value_table({"Algorithm"}, {Align::left}, values);
  for (const Algorithm a : schema::values<Algorithm>()) {
    if (most_iterations(series, values.front(), a) < 0)
      continue;
    std::vector<std::string> row{std::string(schema::to_string(a))};
    for (double v : values) {
      const int it = most_iterations(series, v, a);
      const int nc = count_not_converged(
          series, v, [a](const SweepSeries& s) { return s.base.algorithm == a; });
      row.push_back(it < 0 ? std::string(kMissing)
                           : fmt::format("{}{}", it, nc > 0 ? fmt::format(" ({} n.c.)", nc) : ""));
    }
    iterations.add_row(std::move(row));
  }
  d.set("iterations", iterations.render());
  return d;
}

/// What the pinball does to MPC: its error at each value, and where it failed.
TemplateData pinball(const std::vector<SweepSeries>& series) {
  const auto mpc = curves(
      series,
      [&](const SweepSeries& s) {
        return s.base.algorithm == Algorithm::MPC && on_finest_mesh(s, series);
      },
      true);
  return template_list(mpc, [](const Curve& c) {
    std::vector<double> failed;
    std::vector<std::string> cells;
    for (const auto& p : c.series->points) {
      const auto e = SweepSeries::error(p, c.quantity);
      if (SweepSeries::converged(p) && e)
        cells.push_back(fmt::format("{} at {}", format_percent(*e), format_swept_value(p.value)));
      else
        failed.push_back(p.value);
    }
    TemplateData d("row", c.label());
    d.set("errors", cells.empty() ? std::string("no converged case")
                                  : fmt::format("{}", fmt::join(cells, ", ")));
    d.set("has_failed", !failed.empty());
    d.set("failed", values_text(failed));
    return d;
  });
}

/// From which E ratio on every stress error stays within kSettledPoints of its value at the
/// largest ratio swept.
TemplateData e_ratio(const std::vector<SweepSeries>& series) {
  double latest = 0;
  TemplateData rows{TemplateData::type::list};
  for (const auto& c : curves(series, nullptr, true)) {
    const auto& pts = c.series->points;
    const auto last = SweepSeries::error(pts.back(), c.quantity);
    if (!last)
      continue;
    double settled = pts.back().value;
    for (auto it = pts.rbegin(); it != pts.rend(); ++it) {
      const auto e = SweepSeries::error(*it, c.quantity);
      if (!e || std::abs(*e - *last) > kSettledPoints)
        break;
      settled = it->value;
    }
    latest = std::max(latest, settled);
    TemplateData d("row", c.label());
    d.set("from", format_swept_value(settled));
    d.set("last", format_percent(*last));
    d.set("at", format_swept_value(pts.back().value));
    rows.push_back(d);
  }
  TemplateData d;
  d.set("any", !rows.is_empty_list());
  d.set("rows", rows);
  d.set("settled_points", fmt::format("{:g}", kSettledPoints));
  d.set("latest", format_swept_value(latest));
  d.set("at_smallest", latest == swept_values(series).front());
  return d;
}

std::string key_title(const std::string& key) {
  static const std::map<std::string, std::string> titles{
      {"fkn", "FKN, the normal penalty stiffness"},
      {"ftoln", "FTOLN, the penetration tolerance"},
      {"pinball", "Pinball region"},
      {"E_ratio", "E ratio, indenter over indented body"},
      {"p_over_E", "Load p/E"}};
  const auto it = titles.find(key);
  return it == titles.end() ? key : it->second;
}

/// The answers of one key: those its kind asks for, else the spread of the errors.
void set_answers(TemplateData& d, const ResultsIndex& index, const std::string& key,
                 const std::vector<SweepSeries>& series, const std::vector<double>& values,
                 const schema::StudyReference& study) {
  const auto all = curves(series, nullptr);
  if (key == "fkn") {
    d.set("fkn", fkn(index, series, values, study));
  } else if (key == "pinball") {
    const TemplateData mpc = pinball(series);
    TemplateData p("mpc", mpc);
    p.set("has_mpc", !mpc.is_empty_list());
    d.set("pinball", p);
    if (mpc.is_empty_list())
      d.set("spread", spread(all, key, values));
  } else if (key == "E_ratio") {
    d.set("e_ratio", e_ratio(series));
  } else if (key == "ftoln") {
    const auto al =
        curves(series, [](const SweepSeries& s) { return s.base.algorithm == Algorithm::AL; });
    d.set("spread", spread(al.empty() ? all : al, "FTOLN", values));
  } else {
    d.set("spread", spread(all, key == "p_over_E" ? "p/E" : key, values));
    d.set("load", key == "p_over_E");
  }
}

/// The key's figure (figure_data), or why there is none.
TemplateData key_figure(const FigureSet& figures, const std::string& key) {
  for (const auto& f : figures.figures) {
    if (f.file == sweep_figure_file(key))
      return figure_data(f);
  }
  return figures.unavailable.empty() ? TemplateData(false)
                                     : TemplateData("unavailable", figures.unavailable);
}

}  // namespace

std::string sweep_section(const ResultsIndex& index, const schema::StudyReference& study,
                          const FigureSet& figures) {
  const auto& doc = index.results();
  TemplateData keys{TemplateData::type::list};
  for (const auto& key : swept_keys(doc)) {
    const auto series = sweep_series(doc, key);
    const auto values = swept_values(series);
    if (values.empty())
      continue;
    TemplateData d;
    d.set("title", key_title(key));
    d.set("key", key);
    d.set("n_values", std::to_string(values.size()));
    d.set("values", values_text(values));
    d.set("n_series", std::to_string(series.size()));
    set_answers(d, index, key, series, values, study);
    d.set("figure", key_figure(figures, key));
    d.set("table", error_table(series, values));
    keys.push_back(d);
  }
  if (keys.is_empty_list())
    return {};
  return tidy_markdown(render_template(templates::sweep_section, TemplateData("keys", keys)));
}

}  // namespace cs::reports

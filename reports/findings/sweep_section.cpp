#include "reports/findings/sweep_section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "grading/convergence.hpp"
#include "grading/credibility.hpp"
#include "reports/figures/sweep_figure.hpp"
#include "reports/findings/extent_section.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::Grade;
using schema::Quantity;

bool on_finest_mesh(const ParameterSeries& s, const std::vector<ParameterSeries>& all) {
  return std::ranges::none_of(all, [&](const ParameterSeries& o) {
    return o.spec.problem == s.spec.problem && o.spec.element == s.spec.element &&
           o.spec.mesh > s.spec.mesh;
  });
}

bool stress(const ParameterSeries& s) {
  return s.quantity != Quantity::contact_half_width;  // graded apart: it moves by whole nodes
}

bool penalty_based(const ParameterSeries& s) {
  return schema::traits(s.spec.algorithm).penalty_based;
}

/// The swept values at which every series (not none) is graded `worst` or better (converged).
std::vector<double> values_where_all(const SeriesRefs& series, const std::vector<double>& all,
                                     Grade worst) {
  std::vector<double> out;
  std::ranges::copy_if(all, std::back_inserter(out), [&](double v) {
    return std::ranges::all_of(series, [&](const ParameterSeries* s) {
      const SeriesPoint* p = s->at(v);
      return p && p->error && p->converged() &&
             !schema::is_worse(grading::grade_of_error(*p->error), worst);
    });
  });
  return out;
}

/// The cases of the series `keep` accepts at a value that did not converge.
template <typename Keep>
int count_not_converged(const std::vector<ParameterSeries>& series, double v, Keep&& keep) {
  std::set<const schema::CaseResult*> cases;
  for (const auto& s : series) {
    if (const SeriesPoint* p = keep(s) ? s.at(v) : nullptr; p && !p->converged())
      cases.insert(p->result);
  }
  return static_cast<int>(cases.size());
}

/// The most iterations of the cases of one algorithm at a value, or -1.
int most_iterations(const std::vector<ParameterSeries>& series, double v, Algorithm a) {
  int most = -1;
  for (const auto& s : series) {
    if (const SeriesPoint* p = s.spec.algorithm == a ? s.at(v) : nullptr)
      most = std::max(most, p->iterations);
  }
  return most;
}

/// Whether a point's case passes the interface checks that make a result credible
/// (grading::credibility); a case without checks is not marked.
bool credible(const SeriesPoint& p) {
  return p.result == nullptr || !p.result->interface ||
         grading::credibility(*p.result->interface).credible;
}

/// One value's cell of a series: the signed error, grade (none where the case did not converge)
/// and iterations, or the status of a case without an error.
std::string point_cell(const SeriesPoint* p) {
  if (p == nullptr || !p->error)
    return p ? name_of(p->status) : kMissing;
  const std::string grade = p->converged() ? " " + name_of(grading::grade_of_error(*p->error)) : "";
  return fmt::format("{}{}{}, {} it{}", format_error_resolved(*p->error), grade,
                     credible(*p) ? "" : " ✗", p->iterations,
                     p->converged() ? "" : " (not converged)");
}

/// One key's table: per series on the finest mesh swept, per value its point_cell.
std::string error_table(const std::vector<ParameterSeries>& series,
                        const std::vector<double>& values) {
  constexpr Align l = Align::left, c = Align::center;
  MarkdownTable t = parameter_table({"Problem", "Quantity", "Mesh", "Element", "Option"},
                                    {l, l, c, c, l}, values);
  for (const auto& s : series) {
    if (!on_finest_mesh(s, series))
      continue;
    std::vector<std::string> row = s.label_cells();
    for (double v : values)
      row.push_back(point_cell(s.at(v)));
    t.add_row(std::move(row));
  }
  return t.render();
}

/// The largest spread (max - min, percentage points) of a series' converged errors.
TemplateData spread(const SeriesRefs& series, const std::string& key,
                    const std::vector<double>& values) {
  const auto width = [](const ParameterSeries* s) {
    const auto range = s->error_range();
    return range ? range->second - range->first : -1.0;
  };
  const auto widest = std::ranges::max_element(series, {}, width);  // the first of equals
  const double worst = widest == series.end() ? -1.0 : width(*widest);
  TemplateData d;
  d.set("key", key);
  d.set("values", parameter_window(values, values));
  d.set("spread", fmt::format("{:.3g}", worst));
  d.set("any", worst >= 0);
  // The widest curve is named only where it moves: among curves that do not, none is widest.
  d.set("curve", worst > kSamePoints ? TemplateData((*widest)->label()) : TemplateData(false));
  return d;
}

/// The largest penetration (in h) of the swept AL cases, against the smallest FTOLN swept: AL
/// augments only where a penetration exceeds FTOLN h, so below it the sweep cannot show FTOLN.
TemplateData ftoln_reach(const SeriesRefs& al, const std::vector<double>& values) {
  std::optional<double> deepest;
  for (const ParameterSeries* s : al) {
    for (const SeriesPoint& p : s->points) {
      if (p.result && p.result->interface && p.result->interface->max_penetration_over_h)
        deepest = std::max(deepest.value_or(0.0), *p.result->interface->max_penetration_over_h);
    }
  }
  if (!deepest)
    return TemplateData(false);
  TemplateData d("penetration", fmt::format("{:.2g}", *deepest));
  d.set("smallest", format_parameter(values.front()));
  d.set("below", *deepest < values.front());
  return d;
}

/// AL against PM: the largest |e_AL - e_PM| per value over the series pairs that differ only in
/// the algorithm, and the values where their iteration counts differ.
TemplateData al_pm(const std::vector<ParameterSeries>& series) {
  std::map<double, double> gap;
  std::set<double> iterations_differ;
  for (const ParameterSeries* al : select_series(
           series, [](const ParameterSeries& s) { return s.spec.algorithm == Algorithm::AL; })) {
    schema::CaseSpec pm_spec = al->spec;
    pm_spec.algorithm = Algorithm::PM;
    const auto pm = std::ranges::find_if(series, [&](const ParameterSeries& s) {
      return s.quantity == al->quantity && schema::case_id(s.spec) == schema::case_id(pm_spec);
    });
    if (pm == series.end())
      continue;
    for (const auto& a : al->points) {
      const SeriesPoint* p = pm->at(a.parameter);
      if (p && a.error && p->error)
        gap[a.parameter] = std::max(gap[a.parameter], std::abs(*a.error - *p->error));
      if (p && a.iterations != p->iterations)
        iterations_differ.insert(a.parameter);
    }
  }
  if (gap.empty())
    return TemplateData(false);
  std::vector<double> apart, same;
  for (const auto& [v, g] : gap)
    (g > kSamePoints ? apart : same).push_back(v);
  const auto widest = std::ranges::max_element(gap, {}, [](const auto& vg) { return vg.second; });
  TemplateData d;
  d.set("separate", !apart.empty());
  d.set("apart", parameter_list(apart));
  d.set("widest", fmt::format("{:.3g}", widest->second));
  d.set("widest_at", format_parameter(widest->first));
  d.set("it_apart", parameter_list({iterations_differ.begin(), iterations_differ.end()}));
  d.set("same", parameter_list(same));
  return d;
}

/// Where the errors of `s` cross `target` between two converged points, interpolated in log of
/// the parameter (the errors change with its order of magnitude).
std::vector<std::string> crossings(const ParameterSeries& s, double target) {
  std::vector<std::string> out;
  const SeriesPoint* prev = nullptr;
  for (const auto& p : s.points) {
    if (!p.error || !p.converged())
      continue;
    const double ep = prev ? *prev->error : *p.error;
    if (prev && (ep - target) * (*p.error - target) <= 0 && ep != *p.error) {
      const double t = (target - ep) / (*p.error - ep);
      out.push_back(fmt::format("{:.2g}", std::exp(std::log(prev->parameter) +
                                                   t * std::log(p.parameter / prev->parameter))));
    }
    prev = &p;
  }
  return out;
}

/// The exact value of a series' quantity, from its first point that records one.
std::optional<double> exact_of(const ParameterSeries& s) {
  for (const SeriesPoint& p : s.points) {
    const schema::QuantityResult* q = p.result ? p.result->quantity(s.quantity) : nullptr;
    if (q && std::isfinite(q->exact))
      return q->exact;
  }
  return std::nullopt;
}

/// Can any FKN reproduce the study's AL error on S(1/3) (sigma_c, Q4, ss, mesh F)? Into `d`.
/// Only our own series of the study's option set count (builtin, discretized target, spr).
void set_study_al(TemplateData& d, const std::vector<ParameterSeries>& series,
                  const schema::StudyReference& study) {
  using schema::ProblemId, schema::Element, schema::ContactKind, schema::MeshLevel;
  const auto match = study.find_value(ProblemId::S_1_3, Quantity::sigma_c, Element::Q4,
                                      Algorithm::AL, ContactKind::ss, MeshLevel::F);
  if (match.value == nullptr || !match.value->exact)
    return;
  const SeriesRefs ours = select_series(series, [](const ParameterSeries& s) {
    const schema::CaseSpec& b = s.spec;
    return b.problem == ProblemId::S_1_3 && s.quantity == Quantity::sigma_c &&
           b.algorithm == Algorithm::AL && b.element == Element::Q4 &&
           b.contact == ContactKind::ss && b.mesh == MeshLevel::F && schema::is_baseline(b) &&
           s.error_range();
  });
  const std::optional<double> exact = ours.empty() ? std::nullopt : exact_of(*ours.front());
  if (!exact)
    return;
  // Against the exact value our errors use, so that the study's value and ours are on one basis.
  const double target = grading::error_percent(match.value->value, *exact);
  d.set("printed", match.value->printed);
  d.set("exact", format_value(*exact));
  d.set("study_exact", match.value->exact_printed);
  d.set("target", format_error_resolved(target));
  d.set("study_al", template_list(ours, [&](const ParameterSeries* s) {
          TemplateData r("crossings", joined_or_false(crossings(*s, target), ", "));
          r.set("lo", format_error_resolved(s->error_range()->first));
          r.set("hi", format_error_resolved(s->error_range()->second));
          return r;
        }));
}

/// Whether every swept AL/PM row run on C, M and F converges (the study's c), per value.
TemplateData fkn_convergence(const ResultsIndex& index, const SeriesRefs& series,
                             const std::vector<double>& values) {
  std::map<std::string, const schema::RowVerdict*> rows;
  for (const auto& r : index.results().rows)
    rows[r.id] = &r;
  std::vector<double> converging;
  std::set<const ParameterSeries*> complete;
  for (double v : values) {
    bool every = true, some = false;
    for (const ParameterSeries* s : series) {
      schema::CaseSpec spec = s->spec;
      spec.overrides["fkn"] = v;
      const auto it = rows.find(schema::case_key(spec) + "/" + name_of(s->quantity));
      if (it == rows.end() || !ResultsIndex::complete(*it->second))
        continue;
      some = true;
      complete.insert(s);
      every = every && it->second->converging.value_or(false);
    }
    if (some && every)
      converging.push_back(v);
  }
  if (complete.empty())
    return TemplateData(false);
  // The F cases of the rows at the converging values (a case serves several rows: H_p's two
  // stresses are read from one analysis).
  std::set<std::string> cases, not_credible;
  for (double v : converging) {
    for (const ParameterSeries* s : complete) {
      const SeriesPoint* p = s->at(v);
      if (p == nullptr || (p->result == nullptr && p->row == nullptr))
        continue;
      schema::CaseSpec fine = p->result != nullptr ? p->result->spec : p->row->spec;
      fine.mesh = schema::MeshLevel::F;
      const std::string id = schema::case_id(fine);
      cases.insert(id);
      if (!credible(*p))
        not_credible.insert(id);
    }
  }
  TemplateData d("n", std::to_string(complete.size()));
  d.set("window", converging.empty() ? TemplateData(false)
                                     : TemplateData(parameter_window(converging, values)));
  d.set("not_credible", count_or_false(not_credible.size()));
  d.set("cases", std::to_string(cases.size()));
  return d;
}

/// The default FKN: the smallest at which every swept AL/PM row is e or g (`eg` not empty).
TemplateData fkn_default(const std::vector<ParameterSeries>& series,
                         const std::vector<double>& values, const std::vector<double>& e,
                         const std::vector<double>& eg) {
  TemplateData def;
  const double lo = eg.front();
  def.set("fkn", format_parameter(lo));
  def.set("al_it", std::to_string(most_iterations(series, lo, Algorithm::AL)));
  const int lmp = most_iterations(series, lo, Algorithm::LMP);
  def.set("lmp_it", text_or_false(lmp >= 0 ? std::to_string(lmp) : ""));
  def.set("e_from", e.empty() ? TemplateData(false) : TemplateData(format_parameter(e.front())));
  const auto nc = std::ranges::find_if(values, [&](double v) {
    return v > lo && count_not_converged(series, v, penalty_based) > 0;
  });
  def.set("nc_at", nc == values.end() ? TemplateData(false) : TemplateData(format_parameter(*nc)));
  return def;
}

/// Most iterations of any swept case per algorithm and value, with the cases not converged.
std::string iterations_table(const std::vector<ParameterSeries>& series,
                             const std::vector<double>& values) {
  MarkdownTable t = parameter_table({"Algorithm"}, {Align::left}, values);
  for (const Algorithm a : schema::values<Algorithm>()) {
    if (most_iterations(series, values.front(), a) < 0)
      continue;
    std::vector<std::string> row{name_of(a)};
    for (double v : values) {
      const int it = most_iterations(series, v, a);
      const int nc = count_not_converged(
          series, v, [a](const ParameterSeries& s) { return s.spec.algorithm == a; });
      row.push_back(it < 0 ? std::string(kMissing)
                           : fmt::format("{}{}", it, nc > 0 ? fmt::format(" ({} n.c.)", nc) : ""));
    }
    t.add_row(std::move(row));
  }
  return t.render();
}

TemplateData fkn(const ResultsIndex& index, const std::vector<ParameterSeries>& series,
                 const std::vector<double>& values, const schema::StudyReference& study) {
  const SeriesRefs penalty = select_series(series, [&](const ParameterSeries& s) {
    return penalty_based(s) && shown_in_answers(s, series);
  });
  TemplateData d;
  d.set("any", !penalty.empty());
  if (penalty.empty())
    return d;
  const auto e = values_where_all(penalty, values, Grade::e);
  const auto eg = values_where_all(penalty, values, Grade::g);
  d.set("n_rows", std::to_string(penalty.size()));
  d.set("e", e.empty() ? TemplateData(false) : TemplateData(parameter_window(e, values)));
  d.set("eg",
        eg == e || eg.empty() ? TemplateData(false) : TemplateData(parameter_window(eg, values)));
  d.set("eg_none", eg.empty());
  SeriesRefs never;
  std::ranges::copy_if(penalty, std::back_inserter(never), [&](const ParameterSeries* s) {
    return values_where_all({s}, values, Grade::e).empty();
  });
  d.set("never_e",
        template_list(never, [](const auto* s) { return TemplateData("row", s->label()); }));
  d.set("convergence", fkn_convergence(index, penalty, values));
  std::vector<std::string> not_converged;
  for (double v : values) {
    if (const int n = count_not_converged(series, v, penalty_based); n > 0)
      not_converged.push_back(fmt::format("{} at FKN = {}", n, format_parameter(v)));
  }
  d.set("it_first", std::to_string(most_iterations(series, values.front(), Algorithm::AL)));
  d.set("v_first", format_parameter(values.front()));
  d.set("it_last", std::to_string(most_iterations(series, values.back(), Algorithm::AL)));
  d.set("v_last", format_parameter(values.back()));
  d.set("not_converged", joined_or_false(not_converged, ", "));
  if (!eg.empty())
    d.set("default", fkn_default(series, values, e, eg));
  d.set("al_pm", al_pm(series));
  set_study_al(d, series, study);
  d.set("iterations", iterations_table(series, values));
  return d;
}

/// What the pinball does to MPC: its error at each value, and where it failed.
TemplateData pinball(const std::vector<ParameterSeries>& series) {
  const SeriesRefs mpc = select_series(series, [&](const ParameterSeries& s) {
    return s.spec.algorithm == Algorithm::MPC && shown_in_answers(s, series);
  });
  return template_list(mpc, [](const ParameterSeries* s) {
    std::vector<double> failed;
    std::vector<std::string> cells;
    for (const auto& p : s->points) {
      if (p.converged() && p.error)
        cells.push_back(fmt::format("{}{} at {}", format_error_resolved(*p.error),
                                    credible(p) ? "" : " ✗", format_parameter(p.parameter)));
      else
        failed.push_back(p.parameter);
    }
    TemplateData d("row", s->label());
    d.set("errors", joined_or_false(cells, ", "));
    d.set("failed", failed.empty() ? TemplateData(false) : TemplateData(parameter_list(failed)));
    return d;
  });
}

/// From which E ratio on every stress error stays within the study's resolution
/// (grading::kErrorResolutionPercent) of its value at the
/// largest ratio swept.
TemplateData e_ratio(const std::vector<ParameterSeries>& series, double smallest) {
  double latest = 0;
  TemplateData rows{TemplateData::type::list};
  for (const ParameterSeries* s : select_series(series, stress)) {
    const auto& last = s->points.back();
    if (!last.error)
      continue;
    const auto moved = std::find_if(s->points.rbegin(), s->points.rend(), [&](const auto& p) {
      return !p.error || std::abs(*p.error - *last.error) > grading::kErrorResolutionPercent;
    });
    const double settled = moved.base()->parameter;  // the first point of the settled run
    latest = std::max(latest, settled);
    TemplateData d("row", s->label());
    d.set("from", format_parameter(settled));
    d.set("last", format_error_resolved(*last.error));
    d.set("at", format_parameter(last.parameter));
    rows.push_back(d);
  }
  TemplateData d;
  d.set("any", !rows.is_empty_list());
  d.set("rows", rows);
  d.set("latest", format_parameter(latest));
  d.set("at_smallest", latest == smallest);
  return d;
}

/// The key's title (templates/sweep_titles.mustache), or the key itself.
std::string key_title(const std::string& key) {
  std::string title = render_template(templates::sweep_titles, TemplateData(key, true));
  std::erase(title, '\n');
  return title.empty() ? key : title;
}

/// The answers of one key: those its kind asks for, else the spread of the errors.
void set_answers(TemplateData& d, const ResultsIndex& index, const std::string& key,
                 const std::vector<ParameterSeries>& series, const std::vector<double>& values,
                 const schema::StudyReference& study) {
  const auto all = select_series(series, [](const ParameterSeries&) { return true; });
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
    d.set("e_ratio", e_ratio(series, values.front()));
  } else if (key == "ftoln") {
    const auto al = select_series(
        series, [](const ParameterSeries& s) { return s.spec.algorithm == Algorithm::AL; });
    d.set("spread", spread(al.empty() ? all : al, "FTOLN", values));
    d.set("ftoln_reach", ftoln_reach(al, values));
  } else {
    d.set("spread", spread(all, key == "p_over_E" ? "p/E" : key, values));
    d.set("load", key == "p_over_E");
  }
}

/// The key's figure (figure_data), or why there is none.
TemplateData key_figure(const FigureSet& figures, const std::string& key) {
  const auto f = std::ranges::find(figures.figures, sweep_figure_file(key), &Figure::file);
  if (f != figures.figures.end())
    return figure_data(*f);
  return figures.unavailable.empty() ? TemplateData(false)
                                     : TemplateData("unavailable", figures.unavailable);
}

}  // namespace

std::vector<std::string> run_sweep_keys(const schema::ResultsDocument& doc) {
  std::vector<std::string> keys;
  const auto add = [&](const schema::RunInfo& run) {
    for (const auto& axis : run.sweep) {
      if (std::ranges::find(keys, axis.key) == keys.end())
        keys.push_back(axis.key);
    }
  };
  add(doc.run);
  for (const auto& [source, run] : doc.added_runs)  // files combined by `report --results`
    add(run);
  return keys;
}

std::vector<std::string> swept_keys(const schema::ResultsDocument& doc) {
  std::vector<std::string> keys = run_sweep_keys(doc);
  std::map<std::string, std::set<double>> seen;
  for (const auto& c : doc.cases) {
    if (in_extent_study(c.spec))  // the extent study has a section of its own
      continue;
    for (const auto& [name, value] : c.spec.overrides)
      seen[name].insert(value);
  }
  for (const auto& [name, values] : seen) {
    if (values.size() >= 2 && std::ranges::find(keys, name) == keys.end())
      keys.push_back(name);
  }
  return keys;
}

std::vector<ParameterSeries> sweep_series(const schema::ResultsDocument& doc,
                                          const std::string& key) {
  SeriesGroups sets;  // per option set, its cases; then one series per quantity
  for (const auto& c : doc.cases) {
    const auto it = c.spec.overrides.find(key);
    if (it == c.spec.overrides.end())
      continue;
    ParameterSeries first{c.spec, {}, {}};
    first.spec.overrides.erase(key);
    sets.of(schema::case_id(first.spec), first)
        .points.push_back({.parameter = it->second,
                           .status = c.status,
                           .iterations = c.iterations,
                           .result = &c});
  }
  std::vector<ParameterSeries> out;
  for (const auto& set : std::move(sets).sorted()) {
    for (const auto& q : set.points.front().result->quantities) {
      ParameterSeries& s = out.emplace_back(ParameterSeries{set.spec, q.quantity, {}});
      for (SeriesPoint p : set.points) {  // no error when the case has none
        if (const auto* r = p.result->quantity(q.quantity); r && std::isfinite(r->error_percent))
          p.error = r->error_percent;
        s.points.push_back(p);
      }
    }
  }
  return out;
}

bool shown_in_answers(const ParameterSeries& s, const std::vector<ParameterSeries>& all) {
  return stress(s) && on_finest_mesh(s, all);
}

std::string sweep_section(const ResultsIndex& index, const schema::StudyReference& study,
                          const FigureSet& figures) {
  const auto& doc = index.results();
  TemplateData keys{TemplateData::type::list};
  for (const auto& key : swept_keys(doc)) {
    const auto series = sweep_series(doc, key);
    const auto values =
        parameter_values(select_series(series, [](const ParameterSeries&) { return true; }));
    if (values.empty())
      continue;
    TemplateData d;
    d.set("title", key_title(key));
    d.set("key", key);
    d.set("n_values", std::to_string(values.size()));
    d.set("values", parameter_list(values));
    std::set<std::string> option_sets;
    for (const auto& s : series)
      option_sets.insert(schema::case_id(s.spec));
    d.set("n_series", std::to_string(option_sets.size()));
    set_answers(d, index, key, series, values, study);
    d.set("figure", key_figure(figures, key));
    d.set("table", error_table(series, values));
    keys.push_back(d);
  }
  if (keys.is_empty_list())
    return {};
  TemplateData d("keys", keys);
  d.set("same_points", fmt::format("{:g}", kSamePoints));
  d.set("settled_points", fmt::format("{:g}", grading::kErrorResolutionPercent));
  return tidy_markdown(render_template(templates::sweep_section, d));
}

}  // namespace cs::reports

#include "reports/tables/cross_code_section.hpp"

#include <algorithm>
#include <map>
#include <ranges>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/facts/situation_verdict.hpp"
#include "reports/facts/solvers.hpp"
#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::CaseResult;
using schema::RowVerdict;

bool ours(const std::string& code) {
  return code == builtin_solver_label();
}

/// Counts each other code's options' verdict cells and those among the code's best: the verdict
/// page's situations and rule (SituationVerdict::best), made from that code's rows on that
/// target alone, so that its options are weighed against each other only.
void add_verdict_cells(const ResultsIndex& index, std::vector<OptionTally>& tallies) {
  std::set<std::pair<std::string, schema::TargetKind>> groups;
  for (const auto& t : tallies) {
    if (!ours(t.code))
      groups.insert({t.code, t.target});
  }
  for (const auto& [code, target] : groups) {
    const std::vector<RowFacts> rows = code_row_facts(index, code, target);
    const std::vector<DivergenceFacts> singular = code_divergence_facts(index, code, target);
    for (const SituationVerdict& v : situation_verdicts(index, rows, singular)) {
      for (const OptionCell& c : v.cells) {
        const auto t = std::ranges::find_if(tallies, [&](const OptionTally& t) {
          return t.code == code && t.target == target &&
                 solver_display_name(code) + " " + t.option == c.code;
        });
        if (t == tallies.end())
          continue;
        ++t->cells;
        const bool best = std::ranges::count(v.best, &c) > 0;
        t->best_cells += best && c.worst_grade != schema::Grade::u ? 1 : 0;  // never advise u
      }
    }
  }
}

/// The codes of the results other than ours, in solvers_in's order.
std::vector<std::string> other_codes(const ResultsIndex& index) {
  std::vector<std::string> codes = solvers_in(index);
  std::erase_if(codes, ours);
  return codes;
}

/// Cases and rows that take part: no parameter overrides; ours on patch recovery only.
bool compared(const schema::CaseSpec& s) {
  return s.overrides.empty() && (s.recovery == schema::Recovery::spr ||
                                 (s.recovery == schema::Recovery::own && !ours(code_of(s))));
}

using RowKey = std::tuple<bool, std::string, schema::TargetKind, std::string>;

RowKey key_of(const CodeRow& r) {
  return {!ours(r.code), r.code, r.target, r.option};
}

/// A row's cell on one mesh: the signed error (the value for a singular problem), marked "!"
/// when it is the last iterate of a case that did not converge, else the case's status, else
/// "—".
std::string mesh_cell(const ResultsIndex& index, const RowVerdict* row, std::size_t m) {
  if (row == nullptr)
    return kMissing;
  const std::string mark =
      index.state(*row, kMeshes[m]) == MeshState::not_converged ? std::string("!") : "";
  if (row->errors[m])
    return format_error_resolved(*row->errors[m]) + mark;
  if (row->values[m])
    return format_value(*row->values[m]) + mark;
  const CaseResult* c = index.case_of(*row, kMeshes[m]);
  return c == nullptr || c->status == schema::CaseStatus::converged
             ? std::string(kMissing)
             : std::string(schema::label(c->status));
}

std::string grade_cell(const ResultsIndex& index, const RowVerdict* row) {
  if (row == nullptr)
    return kMissing;
  if (index.state(*row, kFinestMesh) == MeshState::not_converged)
    return "none: F not converged";
  if (row->diverging)
    return *row->diverging ? "diverges (Eq. 47)" : "does not diverge (Eq. 47)";
  if (!row->grade || row->graded_mesh != kFinestMesh)
    return "no grade";
  const std::string g(schema::to_string(*row->grade));
  return (row->converging.value_or(false) ? g + ", c" : g) +
         evidence_marks(facts_of_row(index, *row));
}

std::string checks_cell(const ResultsIndex& index, const RowVerdict* row) {
  if (row == nullptr || !row->values[2])
    return kMissing;
  const RowFacts f = facts_of_row(index, *row);
  if (!f.fine_converged)
    return "not converged";
  if (!index.case_of(*row, schema::MeshLevel::F)->interface)
    return kMissing;
  std::vector<std::string> failed;
  for (const auto& c : f.failures)
    failed.push_back(c.measure ? fmt::format("{} {:.3g}", c.check, *c.measure) : c.check);
  return failed.empty() ? std::string("pass") : join_words(failed, ", ");
}

std::string ansys_cell(const ResultsIndex& index, const schema::StudyReference& study,
                       const RowVerdict& row) {
  const schema::StudyValue* value =
      study
          .find_value(row.spec.problem, row.quantity, row.spec.element, row.spec.algorithm,
                      row.spec.contact, kFinestMesh)
          .value;
  if (value == nullptr)
    return kMissing;
  const auto exact = index.exact_of(row);
  return exact && *exact != 0.0
             ? fmt::format("{} ({})", value->printed,
                           format_error_resolved(grading::error_percent(value->value, *exact)))
             : value->printed;
}

MarkdownTable problem_table(const ResultsIndex& index, const schema::StudyReference& study,
                            const std::vector<CodeRow>& rows) {
  MarkdownTable t({"Code", "Option", "Target", "Study column", "C", "M", "F", "Grade",
                   "F interface checks", "F, own basis", "ANSYS F"});
  for (const auto& r : rows) {
    const RowVerdict& any = *(r.common ? r.common : r.own);
    t.add_row({solver_display_name(r.code), r.option, name_of(r.target),
               Option{any.spec.algorithm, any.spec.contact}.label(), mesh_cell(index, r.common, 0),
               mesh_cell(index, r.common, 1), mesh_cell(index, r.common, 2),
               grade_cell(index, r.common), checks_cell(index, r.common),
               ours(r.code) ? std::string("= common") : mesh_cell(index, r.own, 2),
               ansys_cell(index, study, any)});
  }
  return t;
}

/// Counts a case in its model's line and in the code's total; another code's time only where
/// the case converged (a crash, a time-out or an iteration cap is no solve to time).
void add_case(CostLine& line, CostLine& total, const CaseResult& c, bool is_ours) {
  const bool converged = c.status == schema::CaseStatus::converged;
  for (CostLine* l : {&line, &total}) {
    (is_ours ? l->ours_cases : l->cases) += 1;
    if (is_ours)
      l->ours_seconds += c.wall_seconds;
    else if (converged)
      l->seconds += c.wall_seconds;
    double& peak = is_ours ? l->ours_peak_mb : l->peak_mb;
    peak = std::max(peak, c.peak_rss_mb);
    l->converged += !is_ours && converged ? 1 : 0;
  }
}

/// a / b to 3 digits; "—" unless both are positive (an empty per-case time is 0 / 0).
std::string ratio(double a, double b) {
  return a > 0.0 && b > 0.0 ? fmt::format("{:.3g}", a / b) : std::string(kMissing);
}

std::string per_case(double seconds, int cases) {
  return cases > 0 ? fmt::format("{:.3g}", seconds / cases) : std::string(kMissing);
}

MarkdownTable cost_table(const CodeCost& cost) {
  MarkdownTable t({"Models", fmt::format("{} cases (converged)", solver_display_name(cost.code)),
                   "s per converged case", "peak MB", "ours: cases", "s per case", "peak MB",
                   "time per case, ratio", "memory, ratio"});
  std::vector<CostLine> lines = cost.lines;
  lines.push_back(cost.total);
  for (const CostLine& l : lines) {
    t.add_row(
        {l.label, fmt::format("{} ({})", l.cases, l.converged), per_case(l.seconds, l.converged),
         fmt::format("{:.0f}", l.peak_mb), std::to_string(l.ours_cases),
         per_case(l.ours_seconds, l.ours_cases), fmt::format("{:.0f}", l.ours_peak_mb),
         ratio(l.converged > 0 ? l.seconds / l.converged : 0.0, l.ours_seconds / l.ours_cases),
         ratio(l.peak_mb, l.ours_peak_mb)});
  }
  return t;
}

/// The option's label, with its target where the code has options on both.
std::string option_text(const OptionTally& t, const std::vector<OptionTally>& tallies) {
  const bool both = std::ranges::any_of(
      tallies, [&](const OptionTally& o) { return o.code == t.code && o.target != t.target; });
  return ours(t.code) || both ? fmt::format("{} ({} target)", t.option, schema::to_string(t.target))
                              : t.option;
}

/// "**getfem**: with the discretized target, use nodal_al (best in 9 of 10 verdict cells); ...".
std::string advice_line(const std::vector<OptionTally>& tallies, const std::string& code) {
  TemplateData d("code", solver_display_name(code));
  std::set<schema::TargetKind> targets;
  for (const auto& t : tallies) {
    if (t.code == code)
      targets.insert(t.target);
  }
  // One advice per target the code ran on: its options are counted apart there.
  TemplateData choices{TemplateData::type::list};
  for (const auto target : targets) {
    const auto best = advised(tallies, code, target);
    std::vector<std::string> names;
    for (const OptionTally* t : best)
      names.push_back(t->option);
    TemplateData c("target", targets.size() > 1 ? TemplateData(name_of(target)) : false);
    c.set("advised", text_or_false(join_words(names, " or ")));
    c.set("best_cells", std::to_string(best.empty() ? 0 : best[0]->best_cells));
    c.set("cells", std::to_string(best.empty() ? 0 : best[0]->cells));
    c.set("more", target != *targets.rbegin());
    choices.push_back(c);
  }
  d.set("choices", choices);
  std::string line = render_template(templates::code_advice, d);
  std::erase(line, '\n');
  return line;
}

TemplateData advice_data(const std::vector<OptionTally>& tallies, const std::string& code,
                         const std::vector<SolverOptionMapping>& mappings) {
  TemplateData d("line", advice_line(tallies, code));
  MarkdownTable tally(
      {"Option", "best in verdict cells", "rows with F", "e", "g", "s", "u", "not evidence"});
  for (const auto& x : tallies) {
    if (x.code == code)
      tally.add_row({option_text(x, tallies), fmt::format("{} of {}", x.best_cells, x.cells),
                     std::to_string(x.rows), std::to_string(x.e), std::to_string(x.g),
                     std::to_string(x.s), std::to_string(x.u), std::to_string(x.not_evidence)});
  }
  d.set("tally", tally.render());
  MarkdownTable mapped({"Option", "family", "study column", "what it runs"});
  for (const auto& m : mappings) {
    const std::size_t colon = m.solver.find(':');
    if (m.solver.substr(0, colon) == code)
      mapped.add_row({m.solver.substr(colon + 1), m.fidelity, m.study_option,
                      m.target.empty() ? kMissing : m.target});
  }
  d.set("mapping", text_or_false(rendered_if_any(mapped)));
  return d;
}

PlotSeries curve(std::string title, std::string colour, const std::vector<double>& x,
                 const std::vector<double>& y, bool exact) {
  PlotSeries s{std::move(title), std::move(colour), exact ? Mark::line : Mark::line_points, 1, 7,
               exact ? 2.0 : 1.5};
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
    s.xy.emplace_back(x[i], y[i]);
  return s;
}

/// A panel of (problem, element): the advised options' F profiles, or nullopt without one.
std::optional<PlotPanel> profile_panel(const ResultsIndex& index,
                                       const std::vector<OptionTally>& tallies,
                                       schema::ProblemId problem, schema::Element element) {
  const std::string_view length = schema::symbol(length_scale_of(index, problem));
  PlotPanel panel(
      fmt::format("{} {} (mesh F)", schema::label(problem), schema::to_string(element)),
      {fmt::format("x / {}", length), Scale::linear, std::pair(0.0, length == "b" ? 1.6 : 1.3)},
      {"contact pressure / p"});
  const CaseResult* with_exact = nullptr;
  // code_rows and the tallies are in the same order: ours first, then by code, target, option.
  for (const auto& r : code_rows(index, problem, schema::Quantity::sigma_c, element)) {
    const auto best = advised(tallies, r.code);
    const auto t = std::ranges::find_if(
        best, [&](const OptionTally* t) { return t->option == r.option && t->target == r.target; });
    const CaseResult* c = r.common ? index.case_of(*r.common, schema::MeshLevel::F) : nullptr;
    if (t == best.end() || c == nullptr || c->profile.pressure_over_p.empty())
      continue;
    panel.series.push_back(
        curve(fmt::format("{} {}", solver_display_name(r.code), option_text(**t, tallies)),
              palette_colour(panel.series.size()), c->profile.x_over_a, c->profile.pressure_over_p,
              false));
    with_exact = with_exact ? with_exact : c;
  }
  if (with_exact == nullptr || with_exact->exact_profile.empty())
    return std::nullopt;
  panel.series.push_back(curve("exact", "#000000", with_exact->exact_profile.x_over_a,
                               with_exact->exact_profile.sigma_z_over_p, true));
  return panel;
}

}  // namespace

std::vector<CodeRow> code_rows(const ResultsIndex& index, schema::ProblemId problem,
                               schema::Quantity quantity, schema::Element element) {
  // The study columns (option sets) another code ran `problem` with, per target.
  std::set<std::pair<schema::TargetKind, Option>> columns;
  for (const auto& c : index.results().cases) {
    if (c.spec.problem == problem && !ours(code_of(c.spec)))
      columns.insert({c.spec.target, Option{c.spec.algorithm, c.spec.contact}});
  }
  std::map<RowKey, CodeRow> rows;
  for (const auto& r : index.results().rows) {
    const schema::CaseSpec& s = r.spec;
    if (s.problem != problem || r.quantity != quantity || s.element != element || !compared(s) ||
        !columns.count({s.target, Option{s.algorithm, s.contact}}))
      continue;
    CodeRow row{code_of(s), option_label_of(s), s.target};
    CodeRow& slot = rows.try_emplace(key_of(row), row).first->second;
    (s.recovery == schema::Recovery::own ? slot.own : slot.common) = &r;
  }
  const auto values = std::views::values(rows);
  return {values.begin(), values.end()};
}

std::vector<OptionTally> option_tallies(const ResultsIndex& index) {
  using Cell = std::tuple<schema::ProblemId, schema::Quantity, schema::Element>;
  std::map<RowKey, std::map<Cell, const RowVerdict*>> by_option;
  for (const Slot& s : slots_of(index)) {
    for (const auto& r : code_rows(index, s.problem, s.quantity, s.element)) {
      if (r.common != nullptr && r.common->errors[2] && !index.singular(s.problem))
        by_option[key_of(r)][{s.problem, s.quantity, s.element}] = r.common;
    }
  }
  // Like with like within a code: only the rows every option of the code has on that target
  // (a rigid obstacle's options and the same labels between two meshes solve other problems).
  using Group = std::pair<std::string, schema::TargetKind>;
  std::map<Group, std::set<Cell>> shared;
  for (const auto& [key, rows] : by_option) {
    const auto cells = std::views::keys(rows);
    auto [it, first] =
        shared.try_emplace(Group{std::get<1>(key), std::get<2>(key)}, cells.begin(), cells.end());
    if (!first)
      std::erase_if(it->second, [&](const Cell& c) { return !rows.contains(c); });
  }
  std::vector<OptionTally> out;
  for (const auto& [key, rows] : by_option) {
    OptionTally t{std::get<1>(key), std::get<3>(key), std::get<2>(key)};
    for (const Cell& cell : shared.at(Group{t.code, t.target})) {
      const RowFacts f = facts_of_row(index, *rows.at(cell));
      ++t.rows;
      if (!f.evidence())
        ++t.not_evidence;
      else
        ++(*f.grade == schema::Grade::e   ? t.e
           : *f.grade == schema::Grade::g ? t.g
           : *f.grade == schema::Grade::s ? t.s
                                          : t.u);
    }
    out.push_back(t);
  }
  add_verdict_cells(index, out);
  return out;
}

std::vector<const OptionTally*> advised(const std::vector<OptionTally>& tallies,
                                        const std::string& code,
                                        std::optional<schema::TargetKind> target) {
  const auto counted = [&](const OptionTally& t) {
    return t.code == code && (!target || t.target == *target);
  };
  int best = 0;
  for (const auto& t : tallies)
    best = counted(t) ? std::max(best, t.best_cells) : best;
  std::vector<const OptionTally*> out;
  for (const auto& t : tallies) {
    if (counted(t) && best > 0 && t.best_cells == best)
      out.push_back(&t);
  }
  return out;
}

std::vector<CodeCost> code_costs(const ResultsIndex& index) {
  using Model =
      std::tuple<schema::ProblemId, schema::MeshLevel, schema::Element, schema::TargetKind>;
  const auto model_of = [](const schema::CaseSpec& s) {
    return Model{s.problem, s.mesh, s.element, s.target};
  };
  std::map<Model, std::vector<const CaseResult*>> ours_cases;
  for (const auto& c : index.results().cases) {
    if (ours(code_of(c.spec)) && compared(c.spec))
      ours_cases[model_of(c.spec)].push_back(&c);
  }
  std::map<schema::ProblemId, std::size_t> order;
  for (const schema::ProblemRecord* p : index.problems())
    order.emplace(p->id, order.size());
  std::vector<CodeCost> out;
  for (const auto& code : other_codes(index)) {
    std::map<std::pair<std::size_t, schema::MeshLevel>, CostLine> lines;
    std::set<Model> counted;
    CodeCost cost{code, {}};
    for (const auto& c : index.results().cases) {
      const schema::CaseSpec& s = c.spec;
      if (code_of(s) != code || s.recovery != schema::Recovery::spr || !s.overrides.empty() ||
          !ours_cases.count(model_of(s)))
        continue;
      CostLine& line = lines[{order.count(s.problem) ? order[s.problem] : order.size(), s.mesh}];
      line.label = fmt::format("{} {}", schema::label(s.problem), schema::to_string(s.mesh));
      add_case(line, cost.total, c, false);
      if (counted.insert(model_of(s)).second) {
        for (const CaseResult* o : ours_cases.at(model_of(s)))
          add_case(line, cost.total, *o, true);
      }
    }
    for (auto& [k, l] : lines)
      cost.lines.push_back(std::move(l));
    if (cost.total.cases > 0)
      out.push_back(std::move(cost));
  }
  return out;
}

std::vector<Figure> render_cross_code_figure(const ResultsIndex& index,
                                             const std::filesystem::path& out_root,
                                             const FigureOptions& options) {
  const auto tallies = option_tallies(index);
  Plot plot{
      .title = "Contact pressure of each code's advised option against the exact one (fine mesh)",
      .panel_height = 400,
      .key = KeyPlace::inside,
      .key_columns = 1};
  for (const schema::ProblemId id : {schema::ProblemId::H_p, schema::ProblemId::S_1_3}) {
    for (const auto element : schema::values<schema::Element>()) {
      if (auto panel =
              index.problem(id) ? profile_panel(index, tallies, id, element) : std::nullopt)
        plot.panels.push_back(std::move(*panel));
    }
  }
  if (plot.panels.empty())
    return {};
  Figure figure(FigureKind::profile, "figures/cross_code_profiles.png");
  figure.caption_md = figure_text("cross_code");
  return draw_figures({plot}, {figure}, out_root, options).figures;
}

std::vector<std::string> code_advice_lines(const ResultsIndex& index) {
  if (!is_cross_code(index))
    return {};
  const auto tallies = option_tallies(index);
  std::vector<std::string> out;
  for (const std::string& code : other_codes(index))
    out.push_back(advice_line(tallies, code));
  return out;
}

std::string cross_code_section(const ResultsIndex& index, const schema::StudyReference& study,
                               const std::vector<Figure>& figures,
                               const std::vector<SolverOptionMapping>& mappings,
                               const ResultsIndex* cost_run) {
  if (!is_cross_code(index))
    return {};
  const auto tallies = option_tallies(index);
  TemplateData d("names", solver_names(index));
  d.set("advice", template_list(other_codes(index), [&](const std::string& code) {
          return advice_data(tallies, code, mappings);
        }));
  TemplateData tables{TemplateData::type::list};
  for (const Slot& s : slots_of(index)) {
    const auto rows = code_rows(index, s.problem, s.quantity, s.element);
    if (std::ranges::all_of(rows, [](const CodeRow& r) { return ours(r.code); }))
      continue;
    TemplateData t("title", fmt::format("{} {} ({}), {}", schema::label(s.problem),
                                        schema::description(s.quantity), schema::label(s.quantity),
                                        schema::to_string(s.element)));
    t.set("table", problem_table(index, study, rows).render());
    tables.push_back(t);
  }
  d.set("tables", tables);
  d.set("has_figures", !figures.empty());
  d.set("figures", template_list(figures, figure_data));
  d.set("one_run", cost_run != nullptr);
  if (cost_run) {
    const schema::RunInfo& run = cost_run->results().run;
    d.set("started", run.started_utc);
    d.set("version", run.build().value_or(kMissing));
    std::set<std::string> targets;  // what the run's cases solved against, from the cases
    for (const auto& c : cost_run->results().cases)
      targets.insert(name_of(c.spec.target));
    d.set("cost_targets", join_words(std::vector<std::string>(targets.begin(), targets.end())));
  }
  d.set("costs", template_list(code_costs(cost_run ? *cost_run : index), [](const CodeCost& c) {
          TemplateData t("code", solver_display_name(c.code));
          t.set("table", cost_table(c).render());
          return t;
        }));
  return tidy_markdown(render_template(templates::cross_code_section, d));
}

}  // namespace cs::reports

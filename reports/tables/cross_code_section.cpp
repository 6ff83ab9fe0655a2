#include "reports/tables/cross_code_section.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "reports/facts/row_facts.hpp"
#include "reports/facts/solvers.hpp"
#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"
#include "reports/pages/page_format.hpp"
#include "reports/render/template_text.hpp"

namespace cs::reports {
namespace {

using schema::CaseResult;
using schema::RowVerdict;

bool ours(const std::string& code) {
  return code == builtin_solver_label();
}

/// Cases and rows that take part: no parameter overrides; ours on patch recovery only.
bool compared(const schema::CaseSpec& s) {
  return s.overrides.empty() && (s.recovery == schema::Recovery::spr ||
                                 (s.recovery == schema::Recovery::own && !ours(code_of(s))));
}

/// The study columns (option sets) another code ran `problem` with, per target.
std::set<std::pair<schema::TargetKind, Option>> other_columns(const ResultsIndex& index,
                                                              schema::ProblemId problem) {
  std::set<std::pair<schema::TargetKind, Option>> out;
  for (const auto& c : index.results().cases) {
    if (c.spec.problem == problem && !ours(code_of(c.spec)))
      out.insert({c.spec.target, Option{c.spec.algorithm, c.spec.contact}});
  }
  return out;
}

using RowKey = std::tuple<bool, std::string, schema::TargetKind, std::string>;

RowKey key_of(const CodeRow& r) {
  return {!ours(r.code), r.code, r.target, r.option};
}

std::string target_text(schema::TargetKind t) {
  return std::string(schema::to_string(t));
}

/// A row's cell on one mesh: the signed error (the value for a singular problem), else the
/// case's status, else "—".
std::string mesh_cell(const ResultsIndex& index, const RowVerdict* row, std::size_t m) {
  if (row == nullptr)
    return kMissing;
  if (row->errors[m])
    return format_error_resolved(*row->errors[m]);
  if (row->values[m])
    return format_value(*row->values[m]);
  const CaseResult* c = index.case_of(*row, kMeshes[m]);
  return c == nullptr || c->status == schema::CaseStatus::converged
             ? std::string(kMissing)
             : std::string(schema::label(c->status));
}

std::string grade_cell(const RowVerdict* row) {
  if (row == nullptr)
    return kMissing;
  if (row->diverging)
    return *row->diverging ? "diverges (Eq. 47)" : "does not diverge (Eq. 47)";
  if (!row->grade || row->graded_mesh != kFinestMesh)
    return "no grade";
  const std::string g(schema::to_string(*row->grade));
  return row->converging.value_or(false) ? g + ", c" : g;
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
                       const CodeRow& r) {
  const RowVerdict& row = *(r.common ? r.common : r.own);
  const auto match = study.find_value(row.spec.problem, row.quantity, row.spec.element,
                                      row.spec.algorithm, row.spec.contact, kFinestMesh);
  if (match.value == nullptr)
    return kMissing;
  const auto exact = index.exact_of(row);
  return exact && *exact != 0.0
             ? fmt::format("{} ({})", match.value->printed,
                           format_percent(100.0 * (match.value->value - *exact) / *exact))
             : match.value->printed;
}

MarkdownTable problem_table(const ResultsIndex& index, const schema::StudyReference& study,
                            const std::vector<CodeRow>& rows) {
  MarkdownTable t({"Code", "Option", "Target", "Study column", "C", "M", "F", "Grade",
                   "F interface checks", "F, own basis", "ANSYS F"});
  for (const auto& r : rows) {
    const RowVerdict& any = *(r.common ? r.common : r.own);
    std::vector<std::string> cells{solver_display_name(r.code), r.option, target_text(r.target),
                                   Option{any.spec.algorithm, any.spec.contact}.label()};
    for (std::size_t m = 0; m < kMeshes.size(); ++m)
      cells.push_back(mesh_cell(index, r.common, m));
    cells.push_back(grade_cell(r.common));
    cells.push_back(checks_cell(index, r.common));
    cells.push_back(ours(r.code) ? std::string("= common") : mesh_cell(index, r.own, 2));
    cells.push_back(ansys_cell(index, study, r));
    t.add_row(std::move(cells));
  }
  return t;
}

void add_case(CostLine& line, const CaseResult& c, bool is_ours) {
  (is_ours ? line.ours_cases : line.cases) += 1;
  (is_ours ? line.ours_seconds : line.seconds) += c.wall_seconds;
  double& peak = is_ours ? line.ours_peak_mb : line.peak_mb;
  peak = std::max(peak, c.peak_rss_mb);
  line.converged += !is_ours && c.status == schema::CaseStatus::converged ? 1 : 0;
}

std::string per_case(double seconds, int cases) {
  return cases > 0 ? fmt::format("{:.3g}", seconds / cases) : std::string(kMissing);
}

std::string ratio(double a, double b) {
  return a > 0.0 && b > 0.0 ? fmt::format("{:.3g}", a / b) : std::string(kMissing);
}

MarkdownTable cost_table(const CodeCost& cost) {
  const std::string name = solver_display_name(cost.code);
  MarkdownTable t({"Models", fmt::format("{} cases (converged)", name), "s per case", "peak MB",
                   "ours: cases", "s per case", "peak MB", "time per case, ratio",
                   "memory, ratio"});
  std::vector<const CostLine*> lines;
  for (const auto& l : cost.lines)
    lines.push_back(&l);
  lines.push_back(&cost.total);
  for (const CostLine* l : lines) {
    t.add_row({l->label, fmt::format("{} ({})", l->cases, l->converged),
               per_case(l->seconds, l->cases), fmt::format("{:.0f}", l->peak_mb),
               std::to_string(l->ours_cases), per_case(l->ours_seconds, l->ours_cases),
               fmt::format("{:.0f}", l->ours_peak_mb),
               l->cases > 0 && l->ours_cases > 0
                   ? ratio(l->seconds / l->cases, l->ours_seconds / l->ours_cases)
                   : std::string(kMissing),
               ratio(l->peak_mb, l->ours_peak_mb)});
  }
  return t;
}

std::string tally_text(const OptionTally& t) {
  return fmt::format("e on {} of {} rows", t.e, t.rows);
}

std::string option_text(const OptionTally& t) {
  return ours(t.code) ? fmt::format("{} ({} target)", t.option, target_text(t.target)) : t.option;
}

MarkdownTable tally_table(const std::vector<OptionTally>& tallies, const std::string& code) {
  MarkdownTable t({"Option", "rows with F", "e", "g", "s", "u", "not evidence"});
  for (const auto& x : tallies) {
    if (x.code == code)
      t.add_row({option_text(x), std::to_string(x.rows), std::to_string(x.e), std::to_string(x.g),
                 std::to_string(x.s), std::to_string(x.u), std::to_string(x.not_evidence)});
  }
  return t;
}

TemplateData advice_data(const std::vector<OptionTally>& tallies, const std::string& code,
                         const std::vector<SolverOptionMapping>& mappings) {
  TemplateData d("code", solver_display_name(code));
  std::vector<std::string> names;
  const auto best = advised(tallies, code);
  for (const OptionTally* t : best)
    names.push_back(option_text(*t));
  d.set("advised", text_or_false(join_words(names, " or ")));
  d.set("score", best.empty() ? std::string() : tally_text(*best.front()));
  d.set("tally", tally_table(tallies, code).render());
  MarkdownTable mapped({"Option", "family", "study column", "what it runs"});
  for (const auto& m : mappings) {
    if (m.solver.substr(0, m.solver.find(':')) == code)
      mapped.add_row({m.solver.substr(m.solver.find(':') + 1), m.fidelity, m.study_option,
                      m.target.empty() ? kMissing : m.target});
  }
  d.set("mapping", text_or_false(mapped.n_rows() > 0 ? mapped.render() : std::string()));
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
  for (const auto& code : solvers_in(index)) {
    for (const OptionTally* t : advised(tallies, code)) {
      for (const auto& r : code_rows(index, problem, schema::Quantity::sigma_c, element)) {
        const CaseResult* c = r.common ? index.case_of(*r.common, schema::MeshLevel::F) : nullptr;
        if (r.code != code || r.option != t->option || r.target != t->target || c == nullptr ||
            c->profile.pressure_over_p.empty())
          continue;
        panel.series.push_back(
            curve(fmt::format("{} {}", solver_display_name(code), option_text(*t)),
                  palette_colour(panel.series.size()), c->profile.x_over_a,
                  c->profile.pressure_over_p, false));
        with_exact = with_exact ? with_exact : c;
      }
    }
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
  const auto columns = other_columns(index, problem);
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
  std::vector<CodeRow> out;
  for (auto& [key, row] : rows)
    out.push_back(row);
  return out;
}

std::vector<OptionTally> option_tallies(const ResultsIndex& index) {
  using Cell = std::tuple<schema::ProblemId, schema::Quantity, schema::Element>;
  std::map<RowKey, std::map<Cell, const RowVerdict*>> by_option;
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<schema::Element>()) {
        for (const auto& r : code_rows(index, p->id, q.quantity, element)) {
          if (r.common != nullptr && r.common->errors[2] && !index.singular(p->id))
            by_option[key_of(r)][{p->id, q.quantity, element}] = r.common;
        }
      }
    }
  }
  // Like with like within a code: only the rows every option of the code has.
  std::map<std::string, std::set<Cell>> shared;
  for (const auto& [key, rows] : by_option) {
    std::set<Cell> cells;
    for (const auto& [cell, row] : rows)
      cells.insert(cell);
    auto [it, first] = shared.try_emplace(std::get<1>(key), cells);
    if (!first)
      std::erase_if(it->second, [&](const Cell& c) { return !cells.count(c); });
  }
  std::vector<OptionTally> out;
  for (const auto& [key, rows] : by_option) {
    OptionTally t{std::get<1>(key), std::get<3>(key), std::get<2>(key)};
    for (const Cell& cell : shared.at(t.code)) {
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
  return out;
}

std::vector<const OptionTally*> advised(const std::vector<OptionTally>& tallies,
                                        const std::string& code) {
  int best = 0;
  for (const auto& t : tallies)
    best = t.code == code ? std::max(best, t.e) : best;
  std::vector<const OptionTally*> out;
  for (const auto& t : tallies) {
    if (t.code == code && best > 0 && t.e == best)
      out.push_back(&t);
  }
  return out;
}

std::vector<CodeCost> code_costs(const ResultsIndex& index) {
  using Model =
      std::tuple<schema::ProblemId, schema::MeshLevel, schema::Element, schema::TargetKind>;
  std::map<Model, std::vector<const CaseResult*>> ours_cases;
  for (const auto& c : index.results().cases) {
    if (ours(code_of(c.spec)) && compared(c.spec))
      ours_cases[{c.spec.problem, c.spec.mesh, c.spec.element, c.spec.target}].push_back(&c);
  }
  std::map<schema::ProblemId, std::size_t> order;
  for (const schema::ProblemRecord* p : index.problems())
    order.emplace(p->id, order.size());
  std::vector<CodeCost> out;
  for (const auto& code : solvers_in(index)) {
    if (ours(code))
      continue;
    std::map<std::pair<std::size_t, schema::MeshLevel>, CostLine> lines;
    std::set<Model> counted;
    CodeCost cost;
    cost.code = code;
    for (const auto& c : index.results().cases) {
      const schema::CaseSpec& s = c.spec;
      const Model model{s.problem, s.mesh, s.element, s.target};
      if (code_of(s) != code || s.recovery != schema::Recovery::spr || !s.overrides.empty() ||
          !ours_cases.count(model))
        continue;
      CostLine& line = lines[{order.count(s.problem) ? order[s.problem] : order.size(), s.mesh}];
      line.label = fmt::format("{} {}", schema::label(s.problem), schema::to_string(s.mesh));
      add_case(line, c, false);
      add_case(cost.total, c, false);
      if (counted.insert(model).second) {
        for (const CaseResult* o : ours_cases.at(model)) {
          add_case(line, *o, true);
          add_case(cost.total, *o, true);
        }
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
  Plot plot{"Contact pressure of each code's advised option against the exact one (fine mesh)",
            {},
            2,
            560,
            400,
            KeyPlace::inside,
            1};
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
  GnuplotWriter(options).draw(plot, out_root, figure);
  return {figure};
}

std::string cross_code_section(const ResultsIndex& index, const schema::StudyReference& study,
                               const std::vector<Figure>& figures,
                               const std::vector<SolverOptionMapping>& mappings) {
  if (!is_cross_code(index))
    return {};
  const auto codes = solvers_in(index);
  const auto tallies = option_tallies(index);
  TemplateData d("names", solver_names(index));
  std::vector<std::string> others(codes.begin() + (ours(codes.front()) ? 1 : 0), codes.end());
  d.set("advice", template_list(others, [&](const std::string& code) {
          return advice_data(tallies, code, mappings);
        }));
  std::vector<TemplateData> tables;
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<schema::Element>()) {
        const auto rows = code_rows(index, p->id, q.quantity, element);
        if (std::none_of(rows.begin(), rows.end(), [](const CodeRow& r) { return !ours(r.code); }))
          continue;
        TemplateData t("title", fmt::format("{} {} ({}), {}", schema::label(p->id),
                                            schema::description(q.quantity),
                                            schema::label(q.quantity), schema::to_string(element)));
        t.set("table", problem_table(index, study, rows).render());
        tables.push_back(std::move(t));
      }
    }
  }
  d.set("tables", template_list(tables, [](const TemplateData& t) { return t; }));
  d.set("has_figures", !figures.empty());
  d.set("figures", template_list(figures, figure_data));
  d.set("costs", template_list(code_costs(index), [](const CodeCost& c) {
          TemplateData t("code", solver_display_name(c.code));
          t.set("table", cost_table(c).render());
          return t;
        }));
  return tidy_markdown(render_template(templates::cross_code_section, d));
}

}  // namespace cs::reports

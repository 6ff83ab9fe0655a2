#include "reports/tables/cross_code_section.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "reports/facts/solvers.hpp"
#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"
#include "reports/pages/page_format.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/grade_tables.hpp"

namespace cs::reports {
namespace {

using schema::CaseResult;
using schema::RowVerdict;

/// The rows of every solver for (problem, quantity, element, option), in solvers_in() order.
std::vector<const RowVerdict*> rows_of(const ResultsIndex& index,
                                       const std::vector<std::string>& solvers,
                                       schema::ProblemId problem, schema::Quantity quantity,
                                       schema::Element element, const Option& o) {
  std::vector<const RowVerdict*> out;
  for (const auto& s : solvers)
    out.push_back(solver_row(index, s, problem, quantity, element, o));
  return out;
}

/// The finest mesh of a row whose case did not converge, with its status: "timeout (F)".
std::optional<std::string> unfinished_status(const ResultsIndex& index, const RowVerdict& row) {
  for (auto it = kMeshes.rbegin(); it != kMeshes.rend(); ++it) {
    const CaseResult* c = index.case_of(row, *it);
    if (c != nullptr && c->status != schema::CaseStatus::converged)
      return fmt::format("{} ({})", schema::label(c->status), schema::to_string(*it));
  }
  return std::nullopt;
}

/// A solver's cell on one mesh: "1.2734 (+0.05 %)", the value alone without an error, the
/// case's status without a value, or "—".
std::string value_cell(const ResultsIndex& index, const RowVerdict* row, schema::MeshLevel mesh) {
  const std::size_t m = mesh_index(mesh);
  const CaseResult* c = row ? index.case_of(*row, mesh) : nullptr;
  if (row == nullptr || !row->values[m])
    return c != nullptr && c->status != schema::CaseStatus::converged
               ? std::string(schema::label(c->status))
               : std::string(kMissing);
  return format_value(*row->values[m]) +
         (row->errors[m] ? fmt::format(" ({})", format_percent(*row->errors[m])) : "") +
         (c != nullptr && c->status == schema::CaseStatus::not_converged ? " (not converged)" : "");
}

std::string grade_class(const RowVerdict* row) {
  if (row == nullptr || !row->grade || (row->graded_mesh && *row->graded_mesh != kFinestMesh))
    return "no grade";
  const std::string g(schema::to_string(*row->grade));
  return row->converging.value_or(false) && *row->grade == schema::Grade::e ? g + ", c" : g;
}

/// The options any other solver ran for a Table 2 row of `element`, in all_options() order.
std::vector<Option> table_options(const ResultsIndex& index, const std::vector<StudyRowKey>& rows,
                                  schema::Element element) {
  std::vector<Option> out;
  for (const auto& o : all_options()) {
    if (std::any_of(rows.begin(), rows.end(), [&](const StudyRowKey& r) {
          const auto os = r.quantity ? cross_code_options(index, r.problem, *r.quantity, element)
                                     : std::vector<Option>{};
          return std::find(os.begin(), os.end(), o) != os.end();
        }))
      out.push_back(o);
  }
  return out;
}

/// Per solver, the first case of each same_case_key (spr before other recoveries).
std::vector<std::map<std::string, const CaseResult*>> cases_by_key(
    const ResultsIndex& index, const std::vector<std::string>& solvers) {
  std::vector<std::map<std::string, const CaseResult*>> out(solvers.size());
  for (const auto& c : index.results().cases) {
    const auto s = std::find(solvers.begin(), solvers.end(), schema::solver_label(c.spec));
    auto [it, added] = out[s - solvers.begin()].emplace(same_case_key(c.spec), &c);
    if (!added && c.spec.recovery == schema::Recovery::spr)
      it->second = it->second->spec.recovery == schema::Recovery::spr ? it->second : &c;
  }
  return out;
}

void add(CostLine& line, const std::vector<const CaseResult*>& cases) {
  const std::size_t n = cases.size();
  line.seconds.resize(n);
  line.peak_mb.resize(n);
  line.converged.resize(n);
  ++line.cases;
  for (std::size_t i = 0; i < n; ++i) {
    line.seconds[i] += cases[i]->wall_seconds;
    line.peak_mb[i] = std::max(line.peak_mb[i], cases[i]->peak_rss_mb);
    line.converged[i] += cases[i]->status == schema::CaseStatus::converged ? 1 : 0;
  }
}

std::string ratio_text(const std::optional<double>& r) {
  return r ? fmt::format("{:.3g}", *r) : std::string(kMissing);
}

/// The fine-mesh case of a solver's row of (problem, element, option), or nullptr.
const CaseResult* fine_case(const ResultsIndex& index, const std::string& solver,
                            const schema::ProblemRecord& p, schema::Element element,
                            const Option& o) {
  for (const auto& q : p.quantities) {
    if (const auto* row = solver_row(index, solver, p.id, q.quantity, element, o))
      return index.case_of(*row, kFinestMesh);
  }
  return nullptr;
}

bool has_pressure(const CaseResult* c) {
  return c != nullptr && c->status == schema::CaseStatus::converged &&
         !c->profile.pressure_over_p.empty();
}

/// The option set of a panel (see the header), or nullopt when no other solver ran one.
std::optional<Option> panel_option(const ResultsIndex& index, const schema::ProblemRecord& p,
                                   schema::Element element,
                                   const std::vector<std::string>& solvers) {
  std::optional<Option> fallback;
  for (const auto& o : all_options()) {
    bool other = false, all = true;
    for (const auto& s : solvers) {
      const auto* c = fine_case(index, s, p, element, o);
      other = other || (s != builtin_solver_label() && c != nullptr);
      all = all && has_pressure(c);
    }
    if (other && all)
      return o;
    fallback = other && !fallback ? std::optional(o) : fallback;
  }
  return fallback;
}

PlotSeries curve(std::string title, std::string colour, const std::vector<double>& x,
                 const std::vector<double>& y) {
  const bool exact = title == "exact";
  PlotSeries s{std::move(title), std::move(colour), exact ? Mark::line : Mark::line_points, 1, 7,
               exact ? 2.0 : 1.5};
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
    s.xy.emplace_back(x[i], y[i]);
  return s;
}

CrossCodePanel make_panel(const ResultsIndex& index, const schema::ProblemRecord& p,
                          schema::Element element, const Option& o,
                          const std::vector<std::string>& solvers) {
  CrossCodePanel panel{p.id, element, o, {}, {}};
  const CaseResult* with_exact = nullptr;
  for (const auto& s : solvers) {
    const auto* c = fine_case(index, s, p, element, o);
    if (!has_pressure(c)) {
      panel.missing.push_back(fmt::format("{} ({})", solver_display_name(s),
                                          c == nullptr ? "not run" : schema::label(c->status)));
      continue;
    }
    panel.curves.push_back(curve(solver_display_name(s), palette_colour(panel.curves.size()),
                                 c->profile.x_over_a, c->profile.pressure_over_p));
    with_exact = with_exact == nullptr && !c->exact_profile.empty() ? c : with_exact;
  }
  if (with_exact != nullptr)
    panel.curves.push_back(curve("exact", "#000000", with_exact->exact_profile.x_over_a,
                                 with_exact->exact_profile.sigma_z_over_p));
  return panel;
}

std::string outcome_markdown(const ResultsIndex& index, const std::string& solver) {
  using Counts = std::map<schema::CaseStatus, int>;
  const auto text = [](const Counts& c) {
    std::string out;
    for (const auto& [status, n] : c)
      out += fmt::format("{}{} {}", out.empty() ? "" : ", ", n, schema::label(status));
    return out.empty() ? std::string(kMissing) : out;
  };
  std::vector<std::string> header{"Problem"};
  for (const auto m : kMeshes)
    header.emplace_back(schema::to_string(m));
  MarkdownTable table(header);
  Counts total;
  for (const schema::ProblemRecord* p : index.problems()) {
    std::map<schema::MeshLevel, Counts> by_mesh;
    for (const auto& c : index.results().cases) {
      if (c.spec.problem == p->id && schema::solver_label(c.spec) == solver &&
          c.spec.recovery == schema::Recovery::spr) {
        ++by_mesh[c.spec.mesh][c.status];
        ++total[c.status];
      }
    }
    std::vector<std::string> cells{std::string(schema::label(p->id))};
    for (const auto m : kMeshes)
      cells.push_back(by_mesh.count(m) ? text(by_mesh[m]) : std::string(kMissing));
    if (!by_mesh.empty())
      table.add_row(std::move(cells));
  }
  return fmt::format("**{}**: {} in all.\n\n{}\n", solver_display_name(solver), text(total),
                     table.render());
}

std::string tally_table(const std::map<std::string, GradeTally>& tally,
                        const std::vector<std::string>& solvers) {
  const std::vector<std::string> classes{"e, c", "e", "g", "s", "u", "no grade"};
  std::vector<std::string> header{"Solver", "rows"};
  header.insert(header.end(), classes.begin(), classes.end());
  MarkdownTable table(header);
  for (const auto& s : solvers) {
    if (!tally.count(s))
      continue;
    const GradeTally& t = tally.at(s);
    std::vector<std::string> cells{solver_display_name(s), std::to_string(t.rows)};
    for (const auto& c : classes)
      cells.push_back(std::to_string(t.by_class.count(c) ? t.by_class.at(c) : 0));
    table.add_row(std::move(cells));
  }
  return table.n_rows() == 0 ? std::string() : table.render();
}

TemplateData titled(const std::string& title, const std::string& table) {
  TemplateData t;
  t.set("title", title);
  t.set("table", table);
  return t;
}

}  // namespace

std::string solver_grade_cell(const ResultsIndex& index, const RowVerdict* row) {
  if (row == nullptr)
    return kMissing;
  const auto status = unfinished_status(index, *row);
  if (!row->grade && status)
    return *status;
  const std::string grade = format_grade_cell(index, row);
  // Graded on a coarser mesh because the finer one did not finish: say how it ended.
  return status && row->graded_mesh && *row->graded_mesh != kFinestMesh
             ? fmt::format("{}, {}", grade, *status)
             : grade;
}

std::optional<MarkdownTable> build_cross_code_grade_table(const ResultsIndex& index,
                                                          const schema::StudyReference& study,
                                                          schema::Element element) {
  const auto solvers = solvers_in(index);
  const auto rows = grade_table_rows(index, study);
  const std::vector<Option> options = table_options(index, rows, element);
  if (options.empty())
    return std::nullopt;
  std::vector<std::string> header{"Problem"};
  for (const auto& o : options)
    header.push_back(o.label());
  MarkdownTable t(header);
  for (const auto& r : rows) {
    if (!r.quantity || cross_code_options(index, r.problem, *r.quantity, element).empty())
      continue;
    std::vector<std::string> cells{r.label_md};
    for (const auto& o : options) {
      std::string cell;
      for (const auto* row : rows_of(index, solvers, r.problem, *r.quantity, element, o))
        cell += solver_grade_cell(index, row) + " │ ";
      const schema::StudyGrade* g =
          study.find_grade(r.problem, r.study_row, element, o.algorithm, o.contact);
      cells.push_back(cell + "ANSYS " + (g == nullptr ? std::string(kMissing) : g->cell()));
    }
    t.add_row(std::move(cells));
  }
  return t;
}

std::map<std::string, GradeTally> cross_code_grade_tally(const ResultsIndex& index,
                                                         const schema::StudyReference& study) {
  std::map<std::string, GradeTally> out;
  const auto solvers = solvers_in(index);
  for (const auto& r : grade_table_rows(index, study)) {
    for (const auto element : schema::values<schema::Element>()) {
      const auto options = r.quantity ? cross_code_options(index, r.problem, *r.quantity, element)
                                      : std::vector<Option>{};
      for (const auto& o : options) {
        const auto rows = rows_of(index, solvers, r.problem, *r.quantity, element, o);
        if (std::find(rows.begin(), rows.end(), nullptr) != rows.end())
          continue;  // not run by every solver: not a like-for-like count
        for (std::size_t i = 0; i < solvers.size(); ++i) {
          ++out[solvers[i]].by_class[grade_class(rows[i])];
          ++out[solvers[i]].rows;
        }
      }
    }
  }
  return out;
}

std::vector<std::pair<schema::ProblemId, MarkdownTable>> build_cross_code_appendix(
    const ResultsIndex& index, const schema::StudyReference& study) {
  std::vector<std::pair<schema::ProblemId, MarkdownTable>> out;
  const auto solvers = solvers_in(index);
  std::vector<std::string> header{"Row", "Exact"};
  for (const auto mesh : kMeshes) {
    for (const auto& s : solvers)
      header.push_back(fmt::format("{} {}", schema::to_string(mesh), solver_display_name(s)));
  }
  header.push_back(fmt::format("{} ANSYS", schema::to_string(kFinestMesh)));
  for (const schema::ProblemRecord* p : index.problems()) {
    MarkdownTable t(header);
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<schema::Element>()) {
        for (const auto& o : cross_code_options(index, p->id, q.quantity, element)) {
          const auto rows = rows_of(index, solvers, p->id, q.quantity, element, o);
          const auto any = std::find_if(rows.begin(), rows.end(), [](auto* r) { return r; });
          const auto exact = any == rows.end() ? std::nullopt : index.exact_of(**any);
          std::vector<std::string> cells{fmt::format("{} {} {}", schema::to_string(q.quantity),
                                                     schema::to_string(element), o.label()),
                                         exact ? format_value(*exact) : "∞"};
          for (const auto mesh : kMeshes) {
            for (const auto* r : rows)
              cells.push_back(value_cell(index, r, mesh));
          }
          const auto ansys =
              study.find_value(p->id, q.quantity, element, o.algorithm, o.contact, kFinestMesh);
          cells.push_back(ansys.value == nullptr ? std::string(kMissing) : ansys.value->printed);
          t.add_row(std::move(cells));
        }
      }
    }
    if (t.n_rows() > 0)
      out.emplace_back(p->id, std::move(t));
  }
  return out;
}

std::optional<double> CostLine::time_ratio(std::size_t i) const {
  return seconds.at(0) > 0 ? std::optional(seconds.at(i) / seconds[0]) : std::nullopt;
}

std::optional<double> CostLine::memory_ratio(std::size_t i) const {
  return peak_mb.at(0) > 0 ? std::optional(peak_mb.at(i) / peak_mb[0]) : std::nullopt;
}

std::optional<SolverCost> solver_cost(const ResultsIndex& index) {
  SolverCost out{solvers_in(index), {}, {"all cases"}, {"cases all converged"}};
  const auto by_key = cases_by_key(index, out.solvers);
  std::map<schema::ProblemId, std::size_t> order;
  for (const schema::ProblemRecord* p : index.problems())
    order.emplace(p->id, order.size());
  std::map<std::pair<std::size_t, schema::MeshLevel>, CostLine> lines;
  for (const auto& [key, first] : by_key.front()) {
    std::vector<const CaseResult*> cases;
    for (const auto& solver_cases : by_key) {
      const auto it = solver_cases.find(key);
      if (it != solver_cases.end())
        cases.push_back(it->second);
    }
    if (cases.size() != out.solvers.size())
      continue;  // not run by every solver
    const schema::CaseSpec& s = first->spec;
    CostLine& line = lines[{order.count(s.problem) ? order[s.problem] : order.size(), s.mesh}];
    line.label = fmt::format("{} {}", schema::label(s.problem), schema::to_string(s.mesh));
    add(line, cases);
    add(out.total, cases);
    if (std::all_of(cases.begin(), cases.end(),
                    [](const CaseResult* c) { return c->status == schema::CaseStatus::converged; }))
      add(out.all_converged, cases);
  }
  if (out.total.cases == 0)
    return std::nullopt;
  for (auto& [k, l] : lines)
    out.lines.push_back(std::move(l));
  return out;
}

MarkdownTable cost_table(const SolverCost& cost) {
  std::vector<std::string> header{"Cases", "cases"};
  const std::string first = solver_display_name(cost.solvers.front());
  for (const auto& s : cost.solvers) {
    const std::string name = solver_display_name(s);
    header.insert(header.end(), {name + " converged", name + " (s)", name + " peak (MB)"});
  }
  for (std::size_t i = 1; i < cost.solvers.size(); ++i) {
    const std::string name = solver_display_name(cost.solvers[i]);
    header.insert(header.end(), {fmt::format("time {}/{}", name, first),
                                 fmt::format("memory {}/{}", name, first)});
  }
  MarkdownTable table(header);
  for (const CostLine* l : [&] {
         std::vector<const CostLine*> all;
         for (const auto& l : cost.lines)
           all.push_back(&l);
         return all.push_back(&cost.total), all.push_back(&cost.all_converged), all;
       }()) {
    std::vector<std::string> cells{l->label, std::to_string(l->cases)};
    for (std::size_t i = 0; i < l->seconds.size(); ++i) {
      cells.insert(cells.end(),
                   {std::to_string(l->converged[i]), fmt::format("{:.3g}", l->seconds[i]),
                    fmt::format("{:.0f}", l->peak_mb[i])});
    }
    for (std::size_t i = 1; i < l->seconds.size(); ++i)
      cells.insert(cells.end(), {ratio_text(l->time_ratio(i)), ratio_text(l->memory_ratio(i))});
    if (l->cases > 0)
      table.add_row(std::move(cells));
  }
  return table;
}

std::vector<CrossCodePanel> cross_code_profile_panels(const ResultsIndex& index) {
  std::vector<CrossCodePanel> out;
  const auto solvers = solvers_in(index);
  for (const schema::ProblemId id : {schema::ProblemId::H_p, schema::ProblemId::S_1_3}) {
    const schema::ProblemRecord* p = index.problem(id);
    for (const auto element : schema::values<schema::Element>()) {
      if (const auto o = p ? panel_option(index, *p, element, solvers) : std::nullopt)
        out.push_back(make_panel(index, *p, element, *o, solvers));
    }
  }
  return out;
}

std::vector<Figure> render_cross_code_figure(const ResultsIndex& index,
                                             const std::filesystem::path& out_root,
                                             const FigureOptions& options) {
  const auto panels = cross_code_profile_panels(index);
  if (panels.empty())
    return {};
  Figure figure(FigureKind::profile, "figures/cross_code_profiles.png");
  figure.caption_md = figure_text("cross_code");
  Plot plot{"Contact pressure per solver against the exact one (fine mesh)",
            {},
            2,
            560,
            400,
            KeyPlace::inside,
            1};
  for (const auto& p : panels) {
    for (const auto& m : p.missing) {
      TemplateData note("problem", std::string(schema::to_string(p.problem)));
      note.set("element", std::string(schema::to_string(p.element)));
      note.set("option", p.option.label());
      note.set("solver", m);
      figure.notes.push_back(figure_text("cross_code_missing", note));
    }
    const std::string_view length = schema::symbol(length_scale_of(index, p.problem));
    PlotPanel panel(
        fmt::format("{} {} {} (mesh F)", schema::label(p.problem), schema::to_string(p.element),
                    p.option.label()),
        {fmt::format("x / {}", length), Scale::linear, std::pair(0.0, length == "b" ? 1.6 : 1.3)},
        {"contact pressure / p"});
    panel.series = p.curves;
    plot.panels.push_back(std::move(panel));
  }
  GnuplotWriter(options).draw(plot, out_root, figure);
  return {figure};
}

std::string cross_code_section(const ResultsIndex& index, const schema::StudyReference& study,
                               const std::vector<Figure>& figures,
                               const std::vector<SolverOptionMapping>& mappings) {
  if (!is_cross_code(index))
    return {};
  const auto solvers = solvers_in(index);
  TemplateData d;
  d.set("names", solver_names(index));
  d.set("order", solver_names(index, ", ") + ", ANSYS");
  d.set("outcome", template_list(solvers, [&](const std::string& s) {
          return TemplateData(outcome_markdown(index, s));
        }));
  d.set("tally", text_or_false(tally_table(cross_code_grade_tally(index, study), solvers)));
  std::vector<TemplateData> grades, mapped, appendix;
  for (const auto element : schema::values<schema::Element>()) {
    if (auto t = build_cross_code_grade_table(index, study, element))
      grades.push_back(titled(std::string(schema::to_string(element)), t->render()));
  }
  for (const auto& s : solvers) {
    MarkdownTable table(
        {"study option", fmt::format("{} runs", solver_display_name(s)), "fidelity", "why"});
    for (const auto& m : mappings) {
      if (m.solver == s)
        table.add_row({m.study_option, m.target.empty() ? kMissing : m.target, m.fidelity, m.note});
    }
    if (table.n_rows() > 0)
      mapped.push_back(titled(solver_display_name(s), table.render()));
  }
  for (const auto& [problem, table] : build_cross_code_appendix(index, study))
    appendix.push_back(titled(std::string(schema::label(problem)), table.render()));
  const auto same = [](const TemplateData& t) { return t; };
  d.set("has_grades", !grades.empty());
  d.set("grades", template_list(grades, same));
  d.set("mappings", template_list(mapped, same));
  d.set("has_figures", !figures.empty());
  d.set("figures", template_list(figures, figure_data));
  const auto cost = solver_cost(index);
  d.set("cost", text_or_false(cost ? cost_table(*cost).render() : std::string()));
  d.set("has_appendix", !appendix.empty());
  d.set("appendix", template_list(appendix, same));
  return tidy_markdown(render_template(templates::cross_code_section, d));
}

}  // namespace cs::reports

#include "reports/figures/cross_code_figure.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "reports/figures/gnuplot.hpp"
#include "reports/tables/cross_code_rows.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;
using schema::ProblemId;

constexpr const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};

/// The fine-mesh case of a solver's row of (problem, element, option), or nullptr.
const schema::CaseResult* fine_case(const ResultsIndex& index, const std::string& solver,
                                    const schema::ProblemRecord& p, schema::Element element,
                                    const Option& o) {
  for (const auto& q : p.quantities) {
    if (const auto* row = solver_row(index, solver, p.id, q.quantity, element, o))
      return index.case_of(*row, kFinestMesh);
  }
  return nullptr;
}

bool has_pressure(const schema::CaseResult* c) {
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
    if (other && !fallback)
      fallback = o;
  }
  return fallback;
}

CrossCodePanel make_panel(const ResultsIndex& index, const schema::ProblemRecord& p,
                          schema::Element element, const Option& o,
                          const std::vector<std::string>& solvers) {
  CrossCodePanel panel{p.id, element, o, {}, {}};
  const schema::ExactProfile* exact = nullptr;
  for (const auto& s : solvers) {
    const auto* c = fine_case(index, s, p, element, o);
    if (!has_pressure(c)) {
      panel.missing.push_back(fmt::format("{} ({})", solver_display_name(s),
                                          c == nullptr ? "not run" : schema::label(c->status)));
      continue;
    }
    ProfileCurve curve{solver_display_name(s), {}};
    const auto& pr = c->profile;
    for (std::size_t i = 0; i < pr.x_over_a.size() && i < pr.pressure_over_p.size(); ++i)
      curve.xy.emplace_back(pr.x_over_a[i], pr.pressure_over_p[i]);
    panel.curves.push_back(std::move(curve));
    if (exact == nullptr && !c->exact_profile.empty())
      exact = &c->exact_profile;
  }
  if (exact != nullptr) {
    ProfileCurve curve{"exact", {}};
    for (std::size_t i = 0; i < exact->x_over_a.size() && i < exact->sigma_z_over_p.size(); ++i)
      curve.xy.emplace_back(exact->x_over_a[i], exact->sigma_z_over_p[i]);
    panel.curves.push_back(std::move(curve));
  }
  return panel;
}

std::string panel_script(const CrossCodePanel& panel, const fs::path& work, int index) {
  const bool punch = panel.problem != ProblemId::H_p;
  std::string s = fmt::format(
      "set title {}\nset xlabel {}\nset ylabel 'contact pressure / p'\nset autoscale\n"
      "set xrange [0:{}]\n",
      gnuplot_quote(fmt::format("{} {} {} (mesh F)", schema::to_string(panel.problem),
                                schema::to_string(panel.element), panel.option.label())),
      gnuplot_quote(punch ? "x / b" : "x / a"), punch ? 1.6 : 1.3);
  std::string plots;
  for (std::size_t i = 0; i < panel.curves.size(); ++i) {
    const auto& c = panel.curves[i];
    const fs::path data = work / fmt::format("panel{}_{}.dat", index, i);
    std::ofstream out(data);
    out.precision(10);
    for (const auto& [x, y] : c.xy)
      out << x << ' ' << y << '\n';
    const bool exact = c.title == "exact";
    plots += plots.empty() ? "plot " : ", \\\n     ";
    plots += fmt::format("{} using 1:2 with {} lc rgb '{}' lw {} title {}",
                         gnuplot_quote(data.string()), exact ? "lines" : "linespoints pt 7 ps 0.6",
                         exact ? "#000000" : kColors[i % std::size(kColors)], exact ? 2 : 1.5,
                         gnuplot_quote(c.title));
  }
  return s + (plots.empty() ? "plot NaN notitle" : plots) + "\n";
}

}  // namespace

std::vector<ProblemId> cross_code_figure_problems() {
  return {ProblemId::H_p, ProblemId::S_1_3};
}

std::vector<CrossCodePanel> cross_code_profile_panels(const ResultsIndex& index) {
  std::vector<CrossCodePanel> out;
  const auto solvers = solvers_in(index);
  for (const ProblemId id : cross_code_figure_problems()) {
    const schema::ProblemRecord* p = index.problem(id);
    if (p == nullptr)
      continue;
    for (const auto element : schema::values<schema::Element>()) {
      if (const auto o = panel_option(index, *p, element, solvers))
        out.push_back(make_panel(index, *p, element, *o, solvers));
    }
  }
  return out;
}

std::vector<Figure> render_cross_code_figure(const ResultsIndex& index, const fs::path& out_root,
                                             const FigureOptions& options) {
  const auto panels = cross_code_profile_panels(index);
  if (panels.empty())
    return {};
  Figure figure;
  figure.kind = FigureKind::profile;
  figure.file = "figures/cross_code_profiles.png";
  figure.caption_md =
      "Contact pressure on the fine mesh, one curve per solver, against the exact pressure "
      "(H<sub>p</sub>: x/a; S(1/3): x/b); the option set of each panel is in its title.";
  for (const auto& p : panels) {
    for (const auto& m : p.missing)
      figure.notes.push_back(fmt::format("{} {} {}: no pressure from {}.",
                                         schema::to_string(p.problem), schema::to_string(p.element),
                                         p.option.label(), m));
  }
  const auto gnuplot = find_gnuplot(options.gnuplot_program);
  if (!gnuplot) {
    figure.error = "gnuplot not found";
    return {figure};
  }
  try {
    ScratchDir work;
    const fs::path png = out_root / figure.file;
    std::error_code ec;
    fs::create_directories(png.parent_path(), ec);
    const int cols = panels.size() > 1 ? 2 : 1;
    const int rows = static_cast<int>((panels.size() + 1) / 2);
    std::string script = fmt::format(
        "set terminal {} size {},{} noenhanced\nset output {}\nset grid\n"
        "set key top right\nset multiplot layout {},{} title {}\n",
        gnuplot->terminal, cols * 560, rows * 400 + 40, gnuplot_quote(png.string()), rows, cols,
        gnuplot_quote("Contact pressure per solver against the exact one (fine mesh)"));
    for (std::size_t i = 0; i < panels.size(); ++i)
      script += panel_script(panels[i], work.path(), static_cast<int>(i));
    script += "unset multiplot\nset output\n";
    const fs::path script_file = work.path() / "cross_code.gp";
    std::ofstream(script_file) << script;
    figure.error = run_gnuplot(*gnuplot, script_file, work.path() / "cross_code.log");
    figure.produced =
        figure.error.empty() && fs::is_regular_file(png, ec) && fs::file_size(png, ec) > 0;
    if (!figure.produced && figure.error.empty())
      figure.error = "gnuplot wrote no image";
  } catch (const std::exception& e) {
    figure.error = e.what();
  }
  return {figure};
}

}  // namespace cs::reports

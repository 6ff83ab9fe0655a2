#include "reports/report_writer.hpp"

#include <cctype>

#include <fmt/format.h>

#include "platform/output_transaction.hpp"
#include "reports/bench/bench_results.hpp"
#include "reports/bench/bench_section.hpp"
#include "reports/figures/bench_figure.hpp"
#include "reports/figures/cross_code_figure.hpp"
#include "reports/figures/mesh_figure.hpp"
#include "reports/figures/sweep_figure.hpp"
#include "reports/findings/anomalies_section.hpp"
#include "reports/findings/extent_section.hpp"
#include "reports/findings/findings.hpp"
#include "reports/findings/recommendation_section.hpp"
#include "reports/findings/recovery_section.hpp"
#include "reports/findings/refinement_section.hpp"
#include "reports/findings/regression_report.hpp"
#include "reports/findings/study_conclusions.hpp"
#include "reports/findings/summary_section.hpp"
#include "reports/findings/sweep_section.hpp"
#include "reports/findings/variant_rows.hpp"
#include "reports/results/results_csv.hpp"
#include "reports/tables/appendix_tables.hpp"
#include "reports/tables/beyond_study_section.hpp"
#include "reports/tables/conformal_section.hpp"
#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/cross_code_section.hpp"
#include "reports/tables/divergence_table.hpp"
#include "reports/tables/friction_section.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/interface_table.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/mesh_table.hpp"

namespace cs::reports {
namespace {

/// GitHub's heading anchor: lower case, spaces as '-', ASCII punctuation other than '-' and
/// '_' dropped, other characters kept.
std::string heading_anchor(const std::string& heading) {
  std::string out;
  for (const char c : heading) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 || std::isalnum(u) || c == '-' || c == '_')
      out += static_cast<char>(u < 0x80 ? std::tolower(u) : u);
    else if (c == ' ')
      out += '-';
  }
  return out;
}

}  // namespace

NumberedSections number_sections(const std::vector<std::string>& sections,
                                 const std::vector<std::string>& appendices) {
  NumberedSections out;
  std::string contents = "**Contents:**";
  const auto add = [&](const std::string& section, const std::string& number) {
    if (section.empty())
      return;
    const std::size_t end = section.find('\n');
    std::string title = section.substr(3, end == std::string::npos ? end : end - 3);
    const std::string heading = number + ". " + title;
    const std::size_t colon = title.find(':');
    contents += fmt::format("{} [{}](#{})", out.toc_entries == 0 ? "" : " ·",
                            colon == std::string::npos ? title : title.substr(0, colon),
                            heading_anchor(heading));
    ++out.toc_entries;
    out.body += "## " + heading + (end == std::string::npos ? "\n" : section.substr(end));
  };
  int n = 0;
  for (const auto& s : sections) {
    if (!s.empty())
      add(s, std::to_string(++n));
  }
  char letter = 'A';
  for (const auto& s : appendices) {
    if (!s.empty())
      add(s, std::string("Appendix ") + letter++);
  }
  out.contents = contents + "\n\n";
  return out;
}

std::string variants_section(const ResultsIndex& index) {
  const std::vector<const schema::RowVerdict*> rows = other_variant_rows(index);
  if (rows.empty())
    return {};
  std::vector<std::string> header{"Row", "Variant"};
  for (const auto mesh : kMeshes)
    header.emplace_back(schema::to_string(mesh));
  header.emplace_back("Grade");
  MarkdownTable table(header);
  for (const schema::RowVerdict* r : rows) {
    std::array<std::string, 3> cells;
    for (std::size_t m = 0; m < kMeshes.size(); ++m) {
      cells[m] = format_value(r->values[m]);
      if (r->errors[m])
        cells[m] += fmt::format(" ({})", format_percent(*r->errors[m]));
    }
    std::string grade = format_grade_cell(index, r);
    if (r->diverging)
      grade = *r->diverging ? "diverges" : "does not diverge";
    const schema::CaseSpec& s = r->spec;
    table.add_row({fmt::format("{} {} {} {} {}", schema::to_string(s.problem),
                               schema::to_string(r->quantity), schema::to_string(s.element),
                               schema::to_string(s.algorithm), schema::to_string(s.contact)),
                   variant_of(s), cells[0], cells[1], cells[2], grade});
  }
  return "## Other option sets (rigid target, parameter overrides)\n\n"
         "Not in the study, so not in Tables 2 or the appendix tables: our value (our % error) "
         "per mesh and the grade of the finest mesh.\n\n" +
         table.render() + "\n";
}

std::string report_title(const ResultsIndex& index) {
  if (!is_cross_code(index))
    return "our contact elements beside the study's ANSYS results";
  std::string names;
  const auto solvers = solvers_in(index);
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const char* sep = i == 0 ? "" : (i + 1 == solvers.size() ? " and " : ", ");
    names += sep + solver_display_name(solvers[i]);
  }
  return names + " beside the study's ANSYS results";
}

std::string report_markdown(const ResultsIndex& index, const StudyReference& study,
                            const ReportContent& content) {
  const auto findings = generate_findings(index, study);
  const std::string grades = grade_tables_section(index, study);
  const std::string appendix = appendix_section(index, study);
  const std::string figs = figures_section(content.figures);
  const std::string divergence = divergence_section(index, study);
  const std::string variants = variants_section(index);
  const std::string recovery = recovery_section(index);

  const NumberedSections numbered =
      number_sections({recommendation_section(index),
                       study_conclusions_section(index),
                       summary_section(index, findings),
                       mesh_table_section(index, study),
                       mesh_figures_section(content.mesh_figures),
                       grades,
                       refinement_section(index),
                       appendix,
                       content.cross_code_md,
                       figs,
                       divergence,
                       interface_section(index),
                       anomalies_section(index),
                       beyond_study_section(index),
                       extent_section(index),
                       sweep_section(index, study, content.sweep_figures),
                       friction_section(index),
                       conformal_section(index),
                       variants,
                       recovery},
                      {content.bench_md});

  std::string out =
      "# contact-suite report: " + report_title(index) +
      "\n\n"
      "The battery of Sezer & Sinclair, \"An Assessment of ANSYS Contact Elements\": "
      "frictionless indentation problems with exact solutions, each on three meshes (C, M = "
      "h/2, F = h/4), graded by the study's Eq. 46 (e < 1 % ≤ g < 5 % ≤ s < 10 % ≤ u) on the "
      "fine mesh, with its convergence flag c and, for the singular flat punch, its divergence "
      "test Eq. 47. Every table is built from the results file; the study's values come from "
      "data/study (transcribed from its appendix and Table 2).\n\n";
  out += numbered.contents;
  out += companions_markdown(content.companions);
  if (content.has_regression)
    out += "A regression report against the baseline is in [regression.md](regression.md).\n\n";
  out += "Per-case data for spreadsheets: [results.csv](results.csv).\n\n";
  out += numbered.body;
  return out;
}

ReportOutcome write_report(const schema::ResultsDocument& results, const ReportOptions& options) {
  // Read and check every input before touching the output directory.
  std::optional<schema::ResultsDocument> baseline;
  if (options.baseline)
    baseline = schema::read_results_file(*options.baseline);
  const StudyReference study =
      load_study_reference(options.study_data ? *options.study_data : default_study_data_dir());
  std::optional<BenchResults> bench;
  if (!options.bench.empty())
    bench = load_bench_files(options.bench);
  const ResultsIndex index(results);

  platform::OutputTransaction output(options.out_dir);
  FigureSet figures, bench_figures, mesh_figures, sweep_figures;
  std::vector<Figure> cross_code_figures;
  if (options.figures)
    figures = render_figures(index, output.staging_dir(), options.figure_options);
  if (options.figures && options.mesh_export)
    mesh_figures =
        render_mesh_figures(*options.mesh_export, output.staging_dir(), options.figure_options);
  if (options.figures)
    sweep_figures = render_sweep_figures(results, output.staging_dir(), options.figure_options);
  if (options.figures && is_cross_code(index))
    cross_code_figures =
        render_cross_code_figure(index, output.staging_dir(), options.figure_options);
  if (options.figures && bench)
    bench_figures = render_bench_figures(*bench, output.staging_dir(), {}, options.figure_options);
  const std::string bench_md = bench ? bench_section(*bench, bench_figures) : std::string();
  const std::string cross_code_md =
      cross_code_section(index, study, cross_code_figures, options.option_mappings);
  output.write_text("report.md",
                    report_markdown(index, study,
                                    {figures, mesh_figures, baseline.has_value(), bench_md,
                                     sweep_figures, cross_code_md, options.companions}));
  output.write_text("results.csv", results_csv(index, study));
  if (baseline)
    output.write_text("regression.md", regression_markdown(compare_results(*baseline, results)));

  ReportOutcome outcome;
  outcome.n_cases = static_cast<int>(results.cases.size());
  for (const FigureSet* set : {&figures, &bench_figures, &mesh_figures, &sweep_figures}) {
    for (const auto& f : set->figures)
      (f.produced ? outcome.figures_drawn : outcome.figures_missing)++;
  }
  for (const auto& f : cross_code_figures)
    (f.produced ? outcome.figures_drawn : outcome.figures_missing)++;
  outcome.figures_unavailable =
      figures.unavailable.empty() ? bench_figures.unavailable : figures.unavailable;
  outcome.files = output.commit();
  return outcome;
}

}  // namespace cs::reports

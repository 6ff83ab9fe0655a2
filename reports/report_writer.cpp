#include "reports/report_writer.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "platform/output_transaction.hpp"
#include "reports/bench/bench_results.hpp"
#include "reports/bench/bench_section.hpp"
#include "reports/facts/claims.hpp"
#include "reports/facts/situation_verdict.hpp"
#include "reports/facts/solvers.hpp"
#include "reports/figures/bench_figure.hpp"
#include "reports/figures/mesh_figure.hpp"
#include "reports/figures/sweep_figure.hpp"
#include "reports/findings/anomalies_section.hpp"
#include "reports/findings/extent_section.hpp"
#include "reports/findings/recovery_section.hpp"
#include "reports/findings/refinement_section.hpp"
#include "reports/findings/regression_report.hpp"
#include "reports/findings/sweep_section.hpp"
#include "reports/findings/variant_rows.hpp"
#include "reports/pages/claims_ledger.hpp"
#include "reports/pages/problem_page.hpp"
#include "reports/pages/run_page.hpp"
#include "reports/pages/verdict_page.hpp"
#include "reports/render/template_text.hpp"
#include "reports/report_error.hpp"
#include "reports/results/results_csv.hpp"
#include "reports/tables/appendix_tables.hpp"
#include "reports/tables/conformal_section.hpp"
#include "reports/tables/cross_code_section.hpp"
#include "reports/tables/divergence_table.hpp"
#include "reports/tables/friction_section.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/interface_table.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/mesh_table.hpp"

namespace cs::reports {
namespace {

/// An appendix's key in templates/report.mustache: "appendix-study-tables.md" -> "study_tables".
std::string appendix_key(const std::string& file) {
  std::string key = file.substr(9, file.size() - 12);
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

/// An appendix's file, from its key: "cross_code" -> "appendix-cross-code.md".
std::string appendix_file(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return "appendix-" + key + ".md";
}

/// Part `part` ("title" or "omitted") of the appendix `key` in templates/appendices.mustache.
std::string appendix_text(const std::string& key, const std::string& part) {
  std::string text =
      render_template(templates::appendices, TemplateData(key, TemplateData(part, true)));
  std::erase(text, '\n');
  if (text.empty())
    throw ReportError(fmt::format("templates/appendices.mustache has no {} for {}", part, key));
  return text;
}

/// A section's text without its "## Title" line (its page carries the title).
std::string strip_heading(const std::string& section) {
  if (section.rfind("## ", 0) != 0)
    return section;
  const std::size_t end = section.find('\n');
  return end == std::string::npos ? std::string() : section.substr(end + 1);
}

/// The report's title: with several solvers in the document, their names.
std::string report_title(const ResultsIndex& index) {
  const std::string solvers = solver_names(index);
  return (solvers == "ours" ? "our contact elements" : solvers) +
         " beside the study's ANSYS results";
}

/// The problem pages, one per problem in the results, with their figures.
std::vector<ReportPage> problem_pages(const ResultsIndex& index, const FigureSet& figures,
                                      const FigureSet& mesh_figures) {
  const std::vector<RowFacts> rows = row_facts(index);
  const std::vector<DivergenceFacts> singular = divergence_facts(index);
  std::vector<ReportPage> pages;
  for (const schema::ProblemRecord* p : index.problems()) {
    std::vector<const Figure*> own;
    for (const FigureSet* set : {&mesh_figures, &figures}) {
      for (const auto& f : set->figures) {
        if (f.produced && f.problem == p->id)
          own.push_back(&f);
      }
    }
    pages.push_back({problem_page_file(p->id), std::string(schema::label(p->id)) + ": " + p->title,
                     problem_page(index, *p, rows, singular, own)});
  }
  return pages;
}

}  // namespace

std::string variants_section(const ResultsIndex& index) {
  const std::vector<const schema::RowVerdict*> rows = other_variant_rows(index);
  if (rows.empty())
    return {};
  // The fourth mesh VF where a row has it (the refinement study): shown, not graded.
  const auto vf = [&](const schema::RowVerdict* r) -> const schema::QuantityResult* {
    const schema::CaseResult* c = index.case_of(*r, schema::MeshLevel::VF);
    const schema::QuantityResult* q = index.quantity_of(*r, schema::MeshLevel::VF);
    return c != nullptr && c->status == schema::CaseStatus::converged && q != nullptr &&
                   std::isfinite(q->value)
               ? q
               : nullptr;
  };
  const bool has_vf = std::ranges::any_of(rows, [&](const auto* r) { return vf(r) != nullptr; });
  std::vector<std::string> header{"Row", "Variant"};
  for (const auto mesh : kMeshes)
    header.emplace_back(schema::to_string(mesh));
  if (has_vf)
    header.emplace_back("VF");
  header.emplace_back("Grade");
  const auto cells = [&](const schema::RowVerdict* r) -> std::vector<std::string> {
    const schema::CaseSpec& s = r->spec;
    std::vector<std::string> row{
        fmt::format("{} {} {} {} {}", schema::to_string(s.problem), schema::to_string(r->quantity),
                    schema::to_string(s.element), schema::to_string(s.algorithm),
                    schema::to_string(s.contact)),
        variant_of(s), format_value_and_error(r->values[0], r->errors[0]),
        format_value_and_error(r->values[1], r->errors[1]),
        format_value_and_error(r->values[2], r->errors[2])};
    if (has_vf) {
      const schema::QuantityResult* q = vf(r);
      row.push_back(q == nullptr    ? std::string(kMissing)
                    : q->singular() ? format_value(q->value)
                                    : format_value_and_error(q->value, q->error_percent));
    }
    row.push_back(!r->diverging   ? format_marked_grade_cell(index, r)
                  : *r->diverging ? "diverges"
                                  : "does not diverge");
    return row;
  };
  TemplateData d("table", table_of(header, rows, cells).render());
  d.set("marks_legend", evidence_marks_legend());
  d.set("has_vf", has_vf);
  return render_template(templates::variants_section, d);
}

std::vector<ReportPage> appendix_pages(const ResultsIndex& index,
                                       const schema::StudyReference& study,
                                       const ReportContent& content) {
  // Keyed as in templates/appendices.mustache, which holds their titles.
  const std::pair<std::string, std::string> sections[] = {
      {"tables_2", mesh_table_section(index, study) + grade_tables_section(index, study) +
                       divergence_section(index, study)},
      {"study_tables", appendix_section(index, study)},
      {"meshes", mesh_figures_section(content.mesh_figures)},
      {"estimates", refinement_section(index)},
      {"cross_code", content.cross_code_md},
      {"interface_checks", interface_section(index)},
      {"anomalies", anomalies_section(index)},
      {"extent", extent_section(index)},
      {"sweeps", sweep_section(index, study, content.sweep_figures)},
      {"friction", friction_section(index)},
      {"conformal", conformal_section(index)},
      {"variants", variants_section(index)},
      {"recovery", recovery_section(index)},
      {"benchmarks", content.bench_md},
      {"run", run_page(index.results())},
  };
  std::vector<ReportPage> pages;
  for (const auto& [key, markdown] : sections)
    pages.push_back({appendix_file(key), appendix_text(key, "title"), markdown});
  return pages;
}

std::string report_markdown(const ResultsIndex& index, const ReportContent& content,
                            const std::vector<ReportPage>& problems,
                            const std::vector<ReportPage>& appendices) {
  const std::vector<RowFacts> rows = row_facts(index);
  const std::vector<DivergenceFacts> singular = divergence_facts(index);
  TemplateData d;
  d.set("title", report_title(index));
  d.set("run", run_line(index.results()));
  const OtherCodesNote others{code_advice_lines(index), appendix_file("cross_code"),
                              appendix_text("cross_code", "title")};
  // The verdict sets the other codes' options beside ours; the claims are the study's options.
  std::vector<RowFacts> verdict_rows = other_code_row_facts(index);
  verdict_rows.insert(verdict_rows.begin(), rows.begin(), rows.end());
  std::vector<DivergenceFacts> verdict_singular = other_code_divergence_facts(index);
  verdict_singular.insert(verdict_singular.begin(), singular.begin(), singular.end());
  d.set("verdict",
        verdict_page(index, situation_verdicts(index, verdict_rows, verdict_singular), others));
  d.set("ledger", claims_ledger(study_claims(index, rows, singular, content.bench)));
  const auto links = [](const ReportPage& p) {
    TemplateData l;
    l.set("file", p.file);
    l.set("title", p.title);
    return l;
  };
  d.set("problems", template_list(problems, links));
  std::vector<ReportPage> present;
  std::vector<std::string> omitted;
  for (const ReportPage& p : appendices) {
    if (!p.markdown.empty())
      present.push_back(p);
    else
      omitted.push_back(appendix_text(appendix_key(p.file), "omitted"));
  }
  d.set("appendices", template_list(present, links));
  d.set("omitted",
        template_list(omitted, [](const std::string& r) { return TemplateData("reason", r); }));
  d.set("has_omitted", !omitted.empty());
  d.set("companions", companions_markdown(content.companions, content.writer_version));
  d.set("writer", text_or_false(content.writer_version));
  d.set("has_regression", content.has_regression);
  return tidy_markdown(render_template(templates::report, d));
}

ReportOutcome write_report(const schema::ResultsDocument& results, const ReportOptions& options) {
  // Read and check every input before touching the output directory.
  std::optional<schema::ResultsDocument> baseline;
  if (options.baseline)
    baseline = schema::read_results_file(*options.baseline);
  std::optional<schema::ResultsDocument> cost_run;
  if (options.cost_run)
    cost_run = schema::read_results_file(*options.cost_run);
  const schema::StudyReference study = schema::load_study_reference(
      options.study_data ? *options.study_data : schema::default_study_data_dir());
  std::optional<BenchResults> bench;
  if (!options.bench.empty())
    bench = load_bench_files(options.bench);
  const ResultsIndex index(results);
  std::optional<ResultsIndex> cost_index;
  if (cost_run)
    cost_index.emplace(*cost_run);

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
  const std::string bench_md =
      bench ? bench_section(*bench, bench_figures, {}, &index) : std::string();
  const std::string cross_code_md =
      cross_code_section(index, study, cross_code_figures, options.option_mappings,
                         cost_index ? &*cost_index : nullptr);
  const ReportContent content{figures,
                              mesh_figures,
                              baseline.has_value(),
                              bench_md,
                              sweep_figures,
                              cross_code_md,
                              options.companions,
                              bench ? &*bench : nullptr,
                              options.writer_version};
  const std::vector<ReportPage> problems = problem_pages(index, figures, mesh_figures);
  const std::vector<ReportPage> appendices = appendix_pages(index, study, content);
  for (const auto& page : problems)
    output.write_text(page.file, page.markdown);
  for (const auto& page : appendices) {
    if (!page.markdown.empty())
      output.write_text(page.file, "# " + page.title + "\n\n[← the report](report.md)\n\n" +
                                       strip_heading(page.markdown));
  }
  output.write_text("report.md", report_markdown(index, content, problems, appendices));
  output.write_text("results.csv", results_csv(index, study));
  if (const std::string estimates = estimates_csv(index); !estimates.empty())
    output.write_text("estimates.csv", estimates);
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

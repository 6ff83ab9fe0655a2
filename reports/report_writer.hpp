#pragma once
// `contact-suite report`: everything a results document turns into, written atomically into one
// directory: report.md (the verdict page, the claims ledger, links to one page per problem and to
// the appendices, and a line for each appendix left out for want of its inputs), the problem
// pages, the appendices, figures/*.png, results.csv, estimates.csv (per-row error estimates),
// and with a baseline, regression.md.
//
// The layout of the folder: results/ (the index over a results document, the CSV export),
// facts/ (queries over the results returning structs: rows, verdicts, claims, solvers), pages/
// (the verdict page, the claims ledger, the problem pages), tables/ (the table model, Tables
// 2a′/2b′, the appendix tables, the cross-code comparison), figures/ (the plot model, the gnuplot
// writer, the figures), bench/ (benchmark files and their appendix), findings/ (the other
// appendices, the regression report), render/ (templates/*.mustache, the prose). The study's
// reference data is read by schema/study_reference.hpp.
//
// The report is built from a ResultsDocument in memory (`run` hands over what it ran; `report
// --results FILE` reads the file with schema::read_results_file). All other input is read and
// checked before the output directory is touched: a bad baseline or study data
// (schema::SchemaError) or bench file (ReportError) leaves the directory as it was.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reports/companion_report.hpp"
#include "reports/figures/figures.hpp"
#include "reports/results/results_index.hpp"
#include "reports/tables/cross_code_section.hpp"
#include "schema/results_file.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

struct ReportOptions {
  std::filesystem::path out_dir;  ///< where report.md and the rest go
  /// An older results.json for regression.md, read with schema::read_results_file.
  std::optional<std::filesystem::path> baseline;
  /// Results of every code on the same models in one run (ci/cost-run.sh), read with
  /// schema::read_results_file: the cross-code cost tables (none: from the results' own cases,
  /// which may have run at different times).
  std::optional<std::filesystem::path> cost_run;
  /// data/study with the study's CSVs; default: schema::default_study_data_dir().
  std::optional<std::filesystem::path> study_data;
  /// Google Benchmark JSON files of bench_contact_algorithms: the appendix "Benchmarks"
  /// (none: no such appendix). A case measured in several files is shown from the last.
  std::vector<std::filesystem::path> bench;
  /// A `contact-suite export` directory whose models are drawn as Figure 3 (none: no mesh
  /// pictures).
  std::optional<std::filesystem::path> mesh_export;
  bool figures = true;  ///< draw figures with gnuplot
  FigureOptions figure_options;
  /// How the study's options map to other solvers' (for the cross-code section, shown when the
  /// results hold more than one solver); the command line takes them from the adapters.
  std::vector<SolverOptionMapping> option_mappings;
  /// Other reports linked under the title (read by the caller with read_companion_report).
  std::vector<CompanionReport> companions;
  /// The build that writes the report (e.g. "0.1.0+cc88371"): named at report.md's end, and a
  /// companion written by another build says so. Empty: neither.
  std::string writer_version;
};

/// What write_report produced.
struct ReportOutcome {
  std::vector<std::string> files;  ///< written, relative to out_dir
  int n_cases = 0;
  int figures_drawn = 0, figures_missing = 0;
  std::string figures_unavailable;  ///< why no figure was drawn, if so
};

/// Writes the report of `results` (its `source`, when set, is named in the summary as the
/// results file); throws ReportError for bad study data, a bad bench file or an unwritable
/// directory, schema::SchemaError for a bad baseline.
ReportOutcome write_report(const schema::ResultsDocument& results, const ReportOptions& options);

/// What report.md holds besides the results document and the study's data.
struct BenchResults;

struct ReportContent {
  FigureSet figures;            ///< the figures section's (figures/figures.hpp)
  FigureSet mesh_figures;       ///< Figure 3 (empty: none)
  bool has_regression = false;  ///< link regression.md
  std::string bench_md;         ///< the benchmarks appendix (empty: none)
  FigureSet sweep_figures;      ///< the parameter-sweep section's (figures/sweep_figure.hpp)
  std::string cross_code_md;    ///< the cross-code section (tables/cross_code_section.hpp)
  std::vector<CompanionReport> companions;  ///< other reports linked under the title
  const BenchResults* bench = nullptr;      ///< the benchmarks (claim 7), if given
  std::string writer_version;               ///< ReportOptions::writer_version
};

/// One Markdown file of the report besides report.md: a problem's page or an appendix.
struct ReportPage {
  std::string file;   ///< relative to the report directory, e.g. "problem-H_p.md"
  std::string title;  ///< as report.md links it
  std::string markdown;
};

/// Every appendix in the report's order (the one list of them and their titles); one without
/// content (its inputs are not in the results) has an empty text, is not written, and report.md
/// says why it is absent (templates/report.mustache, keyed by its file name).
std::vector<ReportPage> appendix_pages(const ResultsIndex& index,
                                       const schema::StudyReference& study,
                                       const ReportContent& content);

/// report.md: the verdict page, the claims ledger, and links to the problem pages and the
/// appendices (no I/O).
std::string report_markdown(const ResultsIndex& index, const ReportContent& content,
                            const std::vector<ReportPage>& problems,
                            const std::vector<ReportPage>& appendices);

/// The section listing rows with a rigid target or parameter overrides (empty if none).
std::string variants_section(const ResultsIndex& index);

}  // namespace cs::reports

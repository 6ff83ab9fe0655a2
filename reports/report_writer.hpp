#pragma once
// `contact-suite report`: everything a results file turns into, written atomically into one
// directory: report.md (summary and findings, Tables 2a/2b, appendix tables, figures, the
// flat-punch divergence table, other option sets and, with Google Benchmark JSON of
// bench_contact_algorithms, the benchmarks), figures/*.png, results.csv, and with a baseline,
// regression.md.
//
// All input is read and checked before the output directory is touched: a bad results file,
// baseline, bench file or study data throws ReportError and leaves the directory as it was.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reports/figures.hpp"
#include "reports/results_index.hpp"
#include "reports/study_reference.hpp"

namespace cs::reports {

struct ReportOptions {
  std::filesystem::path results;                  ///< results.json to report on
  std::filesystem::path out_dir;                  ///< where report.md and the rest go
  std::optional<std::filesystem::path> baseline;  ///< older results.json for regression.md
  /// data/study with the study's CSVs; default: default_study_data_dir().
  std::optional<std::filesystem::path> study_data;
  /// Google Benchmark JSON files of bench_contact_algorithms: section 8, "Benchmarks" (none:
  /// no such section). A case measured in several files is shown from the last.
  std::vector<std::filesystem::path> bench;
  bool figures = true;  ///< draw figures with gnuplot
  FigureOptions figure_options;
};

/// What write_report produced.
struct ReportOutcome {
  std::vector<std::string> files;  ///< written, relative to out_dir
  int n_cases = 0;
  int figures_drawn = 0, figures_missing = 0;
  std::string figures_unavailable;  ///< why no figure was drawn, if so
};

/// Writes the report; throws ReportError for bad input or an unwritable directory.
ReportOutcome write_report(const ReportOptions& options);

/// The whole report.md text from its parts (no I/O); `bench_md` is section 8 (empty: none).
std::string report_markdown(const ResultsIndex& index, const StudyReference& study,
                            const FigureSet& figures, bool has_regression,
                            const std::string& bench_md = {});

/// The section listing rows with a rigid target or parameter overrides (empty if none).
std::string variants_section(const ResultsIndex& index);

}  // namespace cs::reports

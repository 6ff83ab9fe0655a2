#pragma once
// Writing what a run produced — results.json and, unless asked not to, its report (report.md,
// results.csv, figures) — into an output directory as one transaction (platform/
// output_transaction.hpp): the directory holds the complete old set or the complete new set,
// never a mix, and a second process writing to it is refused. The report is built from the
// results in memory, not re-read from a file another process may have replaced.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "platform/output_transaction.hpp"
#include "schema/results_file.hpp"

namespace cs::apps {

/// Stages results.json (and the report when `with_report`) and commits `out`. Returns the
/// number of figures drawn (0 without a report); nullopt when an interrupt (SIGINT, SIGTERM)
/// arrived before the commit, e.g. while gnuplot drew: then nothing is committed and the
/// directory keeps its previous set.
std::optional<int> write_run_output(const schema::ResultsDocument& doc,
                                    platform::OutputTransaction& out, bool with_report);

/// The line for an interrupted write: "contact-suite: interrupted: D left as it was".
void report_interrupted_write(const std::string& out_dir);

}  // namespace cs::apps

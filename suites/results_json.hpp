#pragma once
// results.json: the one file a run writes and the reports and the gate read.
// The schema is documented in docs/results-schema.md; bump kResultsSchemaVersion on any
// change a reader would notice.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "suites/case_result.hpp"
#include "suites/row_verdict.hpp"

namespace cs::suites {

inline constexpr const char* kResultsSchemaName = "contact-suite/results";
inline constexpr int kResultsSchemaVersion = 2;

/// What is known about the run as a whole (machine, versions, settings, timing).
struct RunInfo {
  std::string started_utc;     ///< ISO 8601
  double wall_seconds = 0.0;   ///< whole run
  int jobs = 1;                ///< parallel workers
  double peak_rss_mb = 0.0;    ///< process peak resident memory
  std::string command_line;    ///< how the run was started
  nlohmann::json environment;  ///< machine, compiler, library versions, solver settings
};

/// One case as a JSON object: the fields of `contact-suite case --json`.
nlohmann::json to_json(const CaseResult& result);
/// One row verdict as a JSON object.
nlohmann::json to_json(const RowVerdict& row);
/// The whole results document: schema, run, cases, rows.
nlohmann::json make_results_document(const RunInfo& run, const std::vector<CaseResult>& cases);

/// Reads the cases back from a results document (for `report` and `gate`); throws
/// SuiteInputError naming the problem when the document is not a results file of this
/// schema version or a case record is malformed.
std::vector<CaseResult> cases_from_results_document(const nlohmann::json& doc);

}  // namespace cs::suites

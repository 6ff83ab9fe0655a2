#pragma once
// results.json (schema `contact-suite/results`, docs/results-schema.md): the one file a run
// writes and the gate, the report and the scripts read. This is its only reader and writer.
// Bump kResultsSchemaVersion on any change a reader would notice.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "schema/case_result.hpp"
#include "schema/problem_record.hpp"
#include "schema/row_verdict.hpp"

namespace cs::schema {

inline constexpr const char* kResultsSchemaName = "contact-suite/results";
inline constexpr int kResultsSchemaVersion = 4;

/// Which slice of a sharded run a results file holds (`run --shard K/N`).
struct ShardInfo {
  int index = 1;              ///< K, 1-based
  int count = 1;              ///< N
  std::string run_key;        ///< shared by the slices of one run (suites/shard.hpp)
  long long total_cases = 0;  ///< cases of the whole run, over all slices

  friend bool operator==(const ShardInfo&, const ShardInfo&) = default;
};

/// One swept parameter of a run (`run --sweep KEY=V1,V2,...`): its `--set` key and its values in
/// the order given. The run's cases are the cross product of every axis's values.
struct SweepAxis {
  std::string key;
  std::vector<double> values;

  friend bool operator==(const SweepAxis&, const SweepAxis&) = default;
};

/// The most results files one file may say it merges: far beyond any run, so that a merge's
/// sum of them cannot overflow.
inline constexpr int kMaxMergedFiles = 1'000'000;

/// What is known about the run as a whole (machine, versions, settings, timing).
struct RunInfo {
  std::string started_utc;                                ///< ISO 8601
  double wall_seconds = 0.0;                              ///< whole run
  int jobs = 1;                                           ///< parallel workers
  double peak_rss_mb = 0.0;                               ///< process peak resident memory
  std::string command_line;                               ///< how the run was started
  nlohmann::json environment = nlohmann::json::object();  ///< machine, versions, settings
  std::optional<ShardInfo> shard;  ///< set when the file holds one slice of a sharded run
  std::vector<SweepAxis> sweep;    ///< the swept parameters, in the order given; empty: none
  /// Results files `merge` combined into this one (0: one run). Then wall_seconds is summed
  /// over them (machine time) and jobs is the most any one of them ran with.
  int merged_files = 0;
  /// The build that wrote the run (environment's contact_suite_version); nullopt when it is
  /// absent or not a text (the environment is free-form).
  std::optional<std::string> build() const;
};

/// A whole results file.
struct ResultsDocument {
  std::string source;  ///< where it was read from (a path), for messages; empty when built
  RunInfo run;
  std::vector<ProblemRecord> problems;  ///< every problem that has a case, in battery order
  std::vector<CaseResult> cases;
  std::vector<RowVerdict> rows;
  /// Runs combined into this document after the first (schema/combined_results.hpp), each with
  /// its source; empty for a document read from one file. Not written to results.json.
  std::vector<std::pair<std::string, RunInfo>> added_runs;
  /// Per problem, the value of each settable parameter when a case does not set it (`--set`),
  /// from the problem's descriptor: the sweep figures mark it. Empty in files written before.
  std::map<ProblemId, std::map<std::string, double>> parameter_defaults;

  /// The record of a problem, or nullptr.
  const ProblemRecord* problem(ProblemId id) const;
};

/// One case / row / problem as JSON (the fields of `contact-suite case --json` for a case).
nlohmann::json to_json(const CaseResult& result);
nlohmann::json to_json(const RowVerdict& row);
nlohmann::json to_json(const ProblemRecord& problem);
nlohmann::json to_json(const ResultsDocument& doc);

/// Case and row records read back; `path` names the record in messages. Throw SchemaError.
CaseResult case_from_json(const nlohmann::json& j, const std::string& path);
RowVerdict row_from_json(const nlohmann::json& j, const std::string& path);

/// Validates a parsed document: schema name and version, every record typed and named, no
/// duplicate case or row ids, every case's problem in `problems`. Throws SchemaError with a
/// one-line message that starts with `source`.
ResultsDocument results_from_json(const nlohmann::json& doc, const std::string& source);

/// Parses and validates the text of a results file read from `source` (see results_from_json;
/// text that is not JSON or is truncated is a SchemaError too).
ResultsDocument parse_results_text(std::string_view text, const std::string& source);

/// Reads and validates a results file (as parse_results_text; a missing or unreadable file is
/// a SchemaError too).
ResultsDocument read_results_file(const std::filesystem::path& path);

/// Writes a results file atomically (see write_json_file_atomically).
void write_results_file(const std::filesystem::path& path, const ResultsDocument& doc);

}  // namespace cs::schema

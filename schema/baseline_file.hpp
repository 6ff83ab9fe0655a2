#pragma once
// The CI gate's baseline (schema `contact-suite/baseline`): the graded values, statuses and row
// verdicts of a results file, less timings and profiles, with the gate's tolerances. This is
// its only reader and writer; the gate's checks are in suites/gate.hpp.

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "schema/case_result.hpp"
#include "schema/row_verdict.hpp"

namespace cs::schema {

inline constexpr const char* kBaselineSchemaName = "contact-suite/baseline";
inline constexpr int kBaselineSchemaVersion = 3;
/// Survives compiler and BLAS differences; far below any change that matters to a grade.
inline constexpr double kDefaultGateTolerance = 1e-6;

/// Relative tolerances of the value-drift check: a default and per quantity.
struct GateTolerances {
  double default_tolerance = kDefaultGateTolerance;
  std::map<Quantity, double> per_quantity;
  double of(Quantity q) const;
};

/// A baseline: per-case values and statuses, per-row verdicts, tolerances.
struct Baseline {
  GateTolerances tolerances;
  std::vector<CaseResult> cases;  ///< values, grades and statuses only
  std::vector<RowVerdict> rows;
};

nlohmann::json to_json(const Baseline& baseline);

/// Reads a baseline; throws SchemaError naming `source`, the field and the cause (schema,
/// version, malformed record, duplicate id, a tolerance that is not a positive finite number).
Baseline baseline_from_json(const nlohmann::json& doc, const std::string& source);
/// The tolerances of a baseline of any schema version (what --update keeps when it rewrites an
/// older baseline). Throws SchemaError as above.
GateTolerances tolerances_from_json(const nlohmann::json& doc, const std::string& source);

/// Parses and validates the text of a baseline file read from `source` (see
/// baseline_from_json; text that is not JSON or is truncated is a SchemaError too).
Baseline parse_baseline_text(std::string_view text, const std::string& source);
/// Reads a baseline file (as parse_baseline_text; a missing or unreadable file is a
/// SchemaError too).
Baseline read_baseline_file(const std::filesystem::path& path);
void write_baseline_file(const std::filesystem::path& path, const Baseline& baseline);

}  // namespace cs::schema

#pragma once
// Reading and writing whole JSON files with one-line errors (exit 2) and atomic writes.

#include <string>

#include <nlohmann/json.hpp>

namespace cs::apps {

/// Parses the JSON file `path`; throws UsageError naming `what` and the cause (missing,
/// unreadable, not JSON, truncated).
nlohmann::json read_json_file(const std::string& path, const std::string& what);

/// Writes `doc` to `path` through a temporary file in the same directory and a rename, so
/// that `path` is either the old file or the complete new one. Throws UsageError on failure.
void write_json_file_atomically(const std::string& path, const nlohmann::json& doc);

}  // namespace cs::apps

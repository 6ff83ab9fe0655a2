#pragma once
// Whole JSON files: read with one-line errors, written atomically.

#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace cs::schema {

/// Parses JSON text read from `source` (a path, for messages); throws SchemaError naming
/// `what`, the source and the cause (not JSON, truncated, a number out of range, nested deeper
/// than 64 levels, a key given twice in one object).
nlohmann::json parse_json_text(std::string_view text, const std::string& what,
                               const std::string& source);

/// Parses the JSON file `path` (see parse_json_text); throws SchemaError naming `what`, the
/// path and the cause (missing, unreadable, a directory, not JSON, truncated, a number out of
/// range).
nlohmann::json read_json_file(const std::filesystem::path& path, const std::string& what);

/// Writes `doc` to `path` through a temporary file in the same directory and a rename, so that
/// `path` is either the old file or the complete new one. Throws SchemaError on failure.
void write_json_file_atomically(const std::filesystem::path& path, const nlohmann::json& doc);

}  // namespace cs::schema

#pragma once
// Shared helpers of the reports tests: the hand-made results file (data/small_results.json,
// written by data/make_small_results.py, schema v3), read by the one reader of results
// (schema/), the study data of the source tree, a temporary directory, and an edit of one value
// that keeps the case record and its row consistent.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "reports/results/results_index.hpp"
#include "schema/results_file.hpp"
#include "schema/study_reference.hpp"
#include "support/temp_dir.hpp"

namespace cs::reports::testing {

inline std::filesystem::path source_dir() {
  return CONTACT_SUITE_SOURCE_DIR;
}
inline std::filesystem::path sample_path() {
  return source_dir() / "tests" / "reports" / "data" / "small_results.json";
}
inline std::filesystem::path study_dir() {
  return source_dir() / "data" / "study";
}

inline nlohmann::json sample_json() {
  std::ifstream in(sample_path());
  return nlohmann::json::parse(in);
}

/// Appends to `doc`'s cases and rows an edited copy of each whose id `select` accepts (`edit`
/// changes its id and fields); a test that finds none to copy fails.
inline void add_edited_copies(nlohmann::json& doc,
                              const std::function<bool(const std::string&)>& select,
                              const std::function<void(nlohmann::json&)>& edit) {
  for (const std::string key : {"cases", "rows"}) {
    nlohmann::json added = nlohmann::json::array();
    for (const auto& e : doc[key]) {
      if (!select(e["id"].get<std::string>()))
        continue;
      nlohmann::json copy = e;
      edit(copy);
      added.push_back(std::move(copy));
    }
    EXPECT_FALSE(added.empty()) << key;
    for (auto& e : added)
      doc[key].push_back(std::move(e));
  }
}

/// add_edited_copies renaming `from`'s cases and rows (ids "<from>/...") to problem `to`.
inline void copy_problem(nlohmann::json& doc, const std::string& from, const std::string& to,
                         const std::function<bool(const std::string&)>& select) {
  add_edited_copies(
      doc, [&](const std::string& id) { return id.starts_with(from + "/") && select(id); },
      [&](nlohmann::json& e) {
        e["id"] = to + e["id"].get<std::string>().substr(from.size());
        if (e.contains("problem"))
          e["problem"] = to;
        if (e.contains("spec"))
          e["spec"]["problem"] = to;
      });
}

inline const schema::StudyReference& study() {
  static const schema::StudyReference s = schema::load_study_reference(study_dir());
  return s;
}

/// A results document read from JSON by the schema's reader, and its index, kept together
/// (the index references the document).
struct Loaded {
  explicit Loaded(const nlohmann::json& doc)
      : file(schema::results_from_json(doc, "test")), index(file) {}
  schema::ResultsDocument file;
  ResultsIndex index;
};

using cs::testing::TempDir;

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

inline std::string eq46(double error_percent) {
  const double e = std::abs(error_percent);
  return e < 1 ? "e" : e < 5 ? "g" : e < 10 ? "s" : "u";
}

/// A case id less its mesh field: "H_p/F/Q4/LMP/ss" -> "H_p/Q4/LMP/ss".
inline std::string row_key_of(const std::string& case_id) {
  const auto first = case_id.find('/');
  const auto second = case_id.find('/', first + 1);
  return case_id.substr(0, first) + case_id.substr(second);
}

/// Sets the value of `quantity` in case `case_id` (nonsingular) and updates the error and
/// grade of the case and the values, errors and (fine-mesh) grade of its row. The row's
/// converging flag is left as it is: tests that depend on it set it themselves.
inline void set_value(nlohmann::json& doc, const std::string& case_id, const std::string& quantity,
                      double value) {
  for (auto& c : doc["cases"]) {
    if (c["id"] != case_id)
      continue;
    auto& q = c["quantities"][quantity];
    const double exact = q["exact"].get<double>();
    const double err = 100 * (value - exact) / std::abs(exact);
    q["value"] = value;
    q["error_percent"] = err;
    q["grade"] = eq46(err);
    const std::string mesh = c["mesh"];
    const std::string row_id = row_key_of(case_id) + "/" + quantity;
    for (auto& r : doc["rows"]) {
      if (r["id"] != row_id)
        continue;
      r["values"][mesh] = value;
      r["error_percent"][mesh] = err;
      if (r["graded_mesh"] == mesh)
        r["grade"] = eq46(err);
    }
    return;
  }
  ADD_FAILURE() << "no case " << case_id;
}

}  // namespace cs::reports::testing

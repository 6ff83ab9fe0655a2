// Requirement: results.json has one reader and one writer. A document round-trips exactly; every
// malformed field (wrong type, unknown name, out-of-range integer, non-finite number, duplicate
// id) is rejected with a SchemaError naming the field's path, never another exception.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <string>

#include "schema/baseline_file.hpp"
#include "schema/json_file.hpp"
#include "schema/results_file.hpp"
#include "schema/schema_error.hpp"
#include "support/temp_dir.hpp"

namespace cs::schema {
namespace {

using nlohmann::json;

ResultsDocument small_document() {
  ResultsDocument doc;
  doc.run.started_utc = "2026-11-22T00:00:00Z";
  doc.run.wall_seconds = 1.5;
  doc.run.jobs = 2;
  doc.run.command_line = "contact-suite run";
  doc.run.merged_files = 3;
  ProblemRecord p;
  p.id = ProblemId::F_p;
  p.title = "flat punch";
  p.singular = true;
  p.quantities = {{Quantity::sigma_c_star, "md", "plain", "13", ""}};
  doc.problems.push_back(p);
  CaseResult c;
  c.spec.problem = ProblemId::F_p;
  c.spec.mesh = MeshLevel::M;
  c.spec.overrides["fkn"] = 10.0;
  c.status = CaseStatus::converged;
  c.iterations = 3;
  c.wall_seconds = 0.25;
  QuantityResult q;
  q.quantity = Quantity::sigma_c_star;
  q.value = 3.5;
  q.exact = std::numeric_limits<double>::infinity();
  q.error_percent = std::nan("");
  q.contact_pressure = 3.25;
  c.quantities.push_back(q);
  c.profile = {{0.0, 0.5}, {1.0, std::nan("")}, {1.1, 1.2}};
  c.interface = InterfaceChecks{2e-15, 0.0, std::nullopt, 0.25};
  doc.cases.push_back(c);
  RowVerdict row;
  row.spec = c.spec;
  row.spec.mesh = MeshLevel::C;
  row.quantity = Quantity::sigma_c_star;
  row.id = case_key(row.spec) + "/sigma_c_star";
  row.values[1] = 3.5;
  row.diverging = true;
  doc.rows.push_back(row);
  return doc;
}

/// Expects `mutate(doc)` to make the document invalid with a message containing `needle`.
void expect_rejected(const std::function<void(json&)>& mutate, const std::string& needle) {
  json j = to_json(small_document());
  mutate(j);
  try {
    results_from_json(j, "R");
    ADD_FAILURE() << "accepted; expected an error containing: " << needle;
  } catch (const SchemaError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
  }
}

TEST(SchemaResultsFile, RoundTripsEveryField) {
  const ResultsDocument doc = small_document();
  const json once = to_json(doc);
  const ResultsDocument back = results_from_json(once, "mem");
  EXPECT_EQ(to_json(back), once);
  ASSERT_EQ(back.cases.size(), 1u);
  EXPECT_EQ(back.run.merged_files, 3);
  EXPECT_EQ(back.cases[0].spec, doc.cases[0].spec);
  EXPECT_TRUE(back.cases[0].quantities[0].singular());
  EXPECT_TRUE(std::isnan(back.cases[0].profile.sigma_z_over_p[1]));
  EXPECT_EQ(back.rows[0].diverging, std::optional<bool>(true));
  ASSERT_TRUE(back.cases[0].interface);
  EXPECT_EQ(back.cases[0].interface->force_balance, std::optional<double>(2e-15));
  EXPECT_FALSE(back.cases[0].interface->max_outside_over_p);
  EXPECT_EQ(back.cases[0].interface->max_penetration_over_h, std::optional<double>(0.25));
}

// Requirement: where a kept run's files are is a field of its own, so that the reason is the
// same in every run; a file written before the field existed has it split off its reason.
TEST(SchemaResultsFile, KeptFilesRoundTripAndAreSplitOffAnOlderReason) {
  ResultsDocument doc = small_document();
  doc.cases[0].status = CaseStatus::failed;
  doc.cases[0].reason = "*ERROR: too many cutbacks";
  doc.cases[0].kept_files = "/tmp/contact-suite-ccx.AbC/F_p_M";
  const json once = to_json(doc);
  EXPECT_EQ(once["cases"][0]["kept_files"], "/tmp/contact-suite-ccx.AbC/F_p_M");
  EXPECT_EQ(to_json(results_from_json(once, "mem")), once);
  json older = once;
  older["cases"][0].erase("kept_files");
  older["cases"][0]["reason"] =
      "*ERROR: too many cutbacks (CalculiX files kept in /tmp/contact-suite-ccx.AbC/F_p_M)";
  EXPECT_EQ(to_json(results_from_json(older, "old")), once);
  older["cases"][0]["reason"] = "GetFEM's Newton stopped (files kept in /tmp/x (1)/case)";
  const CaseResult c = results_from_json(older, "old").cases[0];
  EXPECT_EQ(c.reason, "GetFEM's Newton stopped");
  EXPECT_EQ(c.kept_files, "/tmp/x (1)/case");
  // A converged case writes no kept_files.
  EXPECT_FALSE(to_json(small_document())["cases"][0].contains("kept_files"));
}

TEST(SchemaResultsFile, RejectsWrongTypesWithTheFieldPath) {
  expect_rejected([](json& j) { j["schema_version"] = "3"; }, "R.schema_version: is a string");
  expect_rejected([](json& j) { j["schema_version"] = 4294967298ULL; }, "out of range");
  expect_rejected([](json& j) { j["schema_version"] = 2; }, "2 is not supported");
  expect_rejected([](json& j) { j["schema"] = "other"; }, "not a contact-suite results file");
  expect_rejected([](json& j) { j["cases"][0]["overrides"] = "fkn=1"; },
                  "R.cases[0].overrides: is a string, expected an object");
  expect_rejected([](json& j) { j["cases"][0]["overrides"]["fkn"] = "10"; },
                  "R.cases[0].overrides.fkn: is a string");
  expect_rejected([](json& j) { j["cases"][0]["reason"] = 5; }, "R.cases[0].reason: is a number");
  expect_rejected([](json& j) { j["cases"][0]["iterations"] = "3"; },
                  "R.cases[0].iterations: is a string");
  expect_rejected([](json& j) { j["cases"][0]["iterations"] = -1; }, "out of range");
  expect_rejected([](json& j) { j["cases"][0]["quantities"]["sigma_c_star"]["study_exact"] = "x"; },
                  "study_exact: is a string");
  expect_rejected([](json& j) { j["cases"][0]["interface"] = "ok"; },
                  "R.cases[0].interface: is a string, expected an object");
  expect_rejected([](json& j) { j["cases"][0]["interface"]["max_tensile_over_p"] = -1.0; },
                  "R.cases[0].interface.max_tensile_over_p: is negative");
  expect_rejected([](json& j) { j["run"]["jobs"] = 2.5; },
                  "R.run.jobs: is a number, expected an integer");
  // Measures cannot be negative, and a time or a count cannot be so large that a merge's sum
  // of them overflows (the report printed the sum, inf, as nan).
  expect_rejected([](json& j) { j["cases"][0]["wall_seconds"] = -1.0; },
                  "R.cases[0].wall_seconds: is negative");
  expect_rejected([](json& j) { j["cases"][0]["element_size_h"] = -0.125; },
                  "R.cases[0].element_size_h: is negative");
  expect_rejected([](json& j) { j["run"]["wall_seconds"] = 1e308; },
                  "R.run.wall_seconds: is above");
  expect_rejected([](json& j) { j["run"]["merged_files"] = 2147483647; }, "out of range");
  // A grade is of one of the study's meshes: a VF graded mesh read past the C, M, F errors.
  expect_rejected([](json& j) { j["rows"][0]["graded_mesh"] = "VF"; },
                  "R.rows[0].graded_mesh: is not one of the study's meshes");
}

TEST(SchemaResultsFile, RejectsUnknownNamesAndDuplicates) {
  expect_rejected([](json& j) { j["cases"][0]["algorithm"] = "ALM"; },
                  "R.cases[0].algorithm: unknown algorithm \"ALM\"");
  expect_rejected([](json& j) { j["cases"][0]["quantities"]["sigma_q"] = json::object(); },
                  "unknown quantity");
  expect_rejected([](json& j) { j["rows"][0]["grade"] = "a"; }, "unknown grade");
  expect_rejected([](json& j) { j["cases"].push_back(j["cases"][0]); }, "duplicate case id");
  expect_rejected([](json& j) { j["cases"][0]["id"] = "x"; }, "does not match its fields");
  expect_rejected([](json& j) { j["problems"] = json::array(); }, "has no entry in 'problems'");
  expect_rejected([](json& j) { j["cases"][0]["solver"] = ""; }, "name the code");
}

// Requirement (issue 14): the run's sweep (keys and values) round-trips; a malformed one is
// refused with its path; a file without it reads as no sweep.
TEST(SchemaResultsFile, SweepRoundTripsAndIsChecked) {
  ResultsDocument doc = small_document();
  EXPECT_FALSE(to_json(doc)["run"].contains("sweep"));
  doc.run.sweep = {{"fkn", {0.1, 1.0, 10.0}}, {"nu", {0.2}}};
  const json once = to_json(doc);
  const ResultsDocument back = results_from_json(once, "mem");
  EXPECT_EQ(back.run.sweep, doc.run.sweep);
  EXPECT_EQ(to_json(back), once);
  expect_rejected([](json& j) { j["run"]["sweep"] = "fkn"; }, "R.run.sweep: is not an array");
  expect_rejected(
      [](json& j) {
        j["run"]["sweep"] = json::array({{{"key", ""}, {"values", {1}}}});
      },
      "R.run.sweep[0].key: is empty");
  expect_rejected(
      [](json& j) {
        j["run"]["sweep"] = json::array({{{"key", "fkn"}, {"values", json::array()}}});
      },
      "R.run.sweep[0].values: is missing or empty");
  expect_rejected(
      [](json& j) {
        j["run"]["sweep"] = json::array({{{"key", "fkn"}, {"values", {1, 1}}}});
      },
      "item 1 repeats item 0");
  expect_rejected(
      [](json& j) {
        j["run"]["sweep"] =
            json::array({{{"key", "fkn"}, {"values", {1}}}, {{"key", "fkn"}, {"values", {2}}}});
      },
      "R.run.sweep[1].key: \"fkn\" is swept twice");
}

// Requirement: the problems' parameter defaults round-trip, and an unknown problem or a
// value that is not a number is refused with its path.
TEST(SchemaResultsFile, ParameterDefaultsRoundTripAndAreChecked) {
  ResultsDocument doc = small_document();
  doc.parameter_defaults[ProblemId::H_p] = {{"fkn", 100.0}, {"nu", 0.25}};
  const json once = to_json(doc);
  const ResultsDocument back = results_from_json(once, "mem");
  EXPECT_EQ(back.parameter_defaults, doc.parameter_defaults);
  EXPECT_EQ(to_json(back), once);
  expect_rejected(
      [](json& j) {
        j["parameter_defaults"] = {{"X_q", {{"fkn", 1}}}};
      },
      "X_q: is not a problem");
  expect_rejected([](json& j) { j["parameter_defaults"] = {{"H_p", {{"fkn", "big"}}}}; }, "fkn");
}

TEST(SchemaResultsFile, FileErrorsAreSchemaErrors) {
  cs::testing::TempDir dir;
  EXPECT_THROW(read_results_file(dir.path() / "missing.json"), SchemaError);
  EXPECT_THROW(read_results_file(dir.path()), SchemaError);  // a directory
  const auto huge = dir.path() / "huge.json";
  std::ofstream(huge) << R"({"schema": "contact-suite/results", "schema_version": 1e999})";
  EXPECT_THROW(read_results_file(huge), SchemaError);
  const auto truncated = dir.path() / "truncated.json";
  std::ofstream(truncated) << to_json(small_document()).dump().substr(0, 40);
  EXPECT_THROW(read_results_file(truncated), SchemaError);
  // A document nested far deeper than ours (copying or writing it would exhaust the stack),
  // and a key given twice (the parser would keep the last silently).
  const auto deep = dir.path() / "deep.json";
  std::string text = to_json(small_document()).dump();
  text.insert(text.rfind('}'), R"(, "x": )" + std::string(100000, '[') + std::string(100000, ']'));
  std::ofstream(deep) << text;
  try {
    read_results_file(deep);
    ADD_FAILURE() << "a document nested 100,000 deep was read";
  } catch (const SchemaError& e) {
    EXPECT_NE(std::string(e.what()).find("nests deeper than 64 levels"), std::string::npos)
        << e.what();
  }
  // The bound itself: 64 levels are read, 65 are not (a root object holding nested arrays).
  const auto nested = [](int arrays) {
    return R"({"a": )" + std::string(arrays, '[') + std::string(arrays, ']') + "}";
  };
  EXPECT_NO_THROW(parse_json_text(nested(63), "results", "64 levels"));
  EXPECT_THROW(parse_json_text(nested(64), "results", "65 levels"), SchemaError);
  const auto twice = dir.path() / "twice.json";
  std::ofstream(twice) << R"({"schema": "contact-suite/results", "schema": "x"})";
  try {
    read_results_file(twice);
    ADD_FAILURE() << "a key given twice was read";
  } catch (const SchemaError& e) {
    EXPECT_NE(std::string(e.what()).find("the key 'schema' is given twice"), std::string::npos)
        << e.what();
  }
  const auto good = dir.path() / "good.json";
  write_results_file(good, small_document());
  EXPECT_EQ(to_json(read_results_file(good)), to_json(small_document()));
}

TEST(SchemaBaselineFile, RoundTripsAndRejectsBadTolerances) {
  Baseline b;
  b.tolerances.per_quantity[Quantity::sigma_c] = 1e-4;
  b.cases = small_document().cases;
  b.rows = small_document().rows;
  const json j = to_json(b);
  const Baseline back = baseline_from_json(j, "B");
  EXPECT_EQ(to_json(back), j);
  EXPECT_EQ(back.tolerances.of(Quantity::sigma_c), 1e-4);
  EXPECT_EQ(back.tolerances.of(Quantity::sigma_h), kDefaultGateTolerance);
  json negative = j;
  negative["tolerances"]["sigma_c"] = -1e-4;
  EXPECT_THROW(baseline_from_json(negative, "B"), SchemaError);
  json zero = j;
  zero["default_tolerance"] = 0;
  EXPECT_THROW(baseline_from_json(zero, "B"), SchemaError);
  json dup = j;
  dup["cases"].push_back(dup["cases"][0]);
  EXPECT_THROW(baseline_from_json(dup, "B"), SchemaError);
}

}  // namespace
}  // namespace cs::schema

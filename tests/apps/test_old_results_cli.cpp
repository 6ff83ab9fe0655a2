// A results file written before the problem records held the situation and the length scale
// still reads: `merge` writes the records again from the catalogue, and `report` fills in what a
// record lacks, so the advice and the figures find every problem the catalogue knows.

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"

namespace cs::apps {
namespace {

using nlohmann::json;
using testing::read_text;
using testing::run_cli;
using testing::TempDir;

/// Runs P_p (Q4 LMP ss, C, M, F: well under a second) into `dir`/run and writes
/// `dir`/old.json, the same results with the problem records as they were before the records
/// carried `situation` and `length_scale`.
std::string old_style_results(const std::string& dir) {
  const auto r = run_cli({"run", "--problems", "P_p", "--elements", "Q4", "--algorithms", "LMP",
                          "--contacts", "ss", "--jobs", "1", "--no-report", "--out", dir + "/run"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  json doc = json::parse(read_text(dir + "/run/results.json"));
  EXPECT_EQ(doc["problems"][0]["situation"], "matched_patch");  // a run writes them
  EXPECT_EQ(doc["problems"][0]["length_scale"], "contact_half_width_a");
  for (auto& p : doc["problems"]) {
    p.erase("situation");
    p.erase("length_scale");
  }
  const std::string path = dir + "/old.json";
  std::ofstream(path) << doc.dump(1);
  return path;
}

// Requirement: `merge` of an old-style file writes records with the catalogue's situation and
// length scale.
TEST(OldResultsCli, MergeRefreshesTheProblemRecords) {
  TempDir tmp;
  const std::string dir = tmp.path().string();
  const std::string old = old_style_results(dir);
  const auto r = run_cli({"merge", dir + "/merged", "--no-report", old});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json merged = json::parse(read_text(dir + "/merged/results.json"));
  ASSERT_EQ(merged["problems"].size(), 1U);
  EXPECT_EQ(merged["problems"][0]["situation"], "matched_patch");
  EXPECT_EQ(merged["problems"][0]["length_scale"], "contact_half_width_a");
}

// Requirement: `report` on an old-style file gives the verdict for the problem's situation (the
// verdict matrix has its column), which it can only find in the refreshed record.
TEST(OldResultsCli, ReportRefreshesTheProblemRecords) {
  TempDir tmp;
  const std::string dir = tmp.path().string();
  const std::string old = old_style_results(dir);
  const auto r = run_cli({"report", "--results", old, "--out", dir + "/report", "--no-figures"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = read_text(dir + "/report/report.md");
  EXPECT_NE(report.find("| Option | Flat contact, nodes aligned |"), std::string::npos)
      << report.substr(0, 2000);
}

}  // namespace
}  // namespace cs::apps

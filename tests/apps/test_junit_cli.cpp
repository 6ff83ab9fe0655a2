// `run --junit` and `gate --junit` end to end: the XML validates against the JUnit schema
// (tests/ci/junit.xsd, with xmllint), a drifted baseline fails exactly the rows it drifted with
// the gate's reasons, the gate's XML and summary of a fixed fixture equal their gold files
// byte for byte, and an unwritable --junit path is refused before anything runs.
//
// Gold files (tests/ci/gold/) are regenerated, after a deliberate change of the format, by
// running this test with CONTACT_SUITE_UPDATE_GOLD=1 and reviewing the diff.

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "cli_support.hpp"

namespace cs::apps {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_cli;
using testing::TempDir;

const fs::path kSource = CONTACT_SUITE_SOURCE_DIR;
const fs::path kFixture = kSource / "tests/reports/data/small_results.json";
const fs::path kSchema = kSource / "tests/ci/junit.xsd";
const fs::path kGold = kSource / "tests/ci/gold";

/// The fixture's own baseline, written by `gate --update` into `dir`.
fs::path fixture_baseline(const fs::path& dir) {
  const fs::path baseline = dir / "baseline.json";
  const auto r = run_cli(
      {"gate", "--update", "--baseline", baseline.string(), "--results", kFixture.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return baseline;
}

/// xmllint's verdict on `xml` against the JUnit schema (true: valid); its messages in `log`.
bool validates(const fs::path& xml, std::string& log) {
  const fs::path out = xml.string() + ".xmllint";
  const std::string command = "xmllint --noout --schema '" + kSchema.string() + "' '" +
                              xml.string() + "' >'" + out.string() + "' 2>&1";
  const int rc = std::system(command.c_str());
  log = read_text(out);
  return rc == 0;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// Compares `actual` with the gold file `name` (rewriting it when CONTACT_SUITE_UPDATE_GOLD=1).
void expect_gold(const std::string& actual, const std::string& name) {
  const fs::path gold = kGold / name;
  if (const char* update = std::getenv("CONTACT_SUITE_UPDATE_GOLD"); update && *update == '1')
    write_text(gold, actual);
  EXPECT_EQ(actual, read_text(gold)) << "differs from " << gold;
}

/// Every testcase that holds an element `child`, by name, with that element's messages.
std::map<std::string, std::vector<std::string>> testcases_with(const fs::path& xml,
                                                               const char* child) {
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_file(xml.c_str())) << xml;
  std::map<std::string, std::vector<std::string>> out;
  for (const auto& suite : doc.child("testsuites").children("testsuite")) {
    for (const auto& tc : suite.children("testcase")) {
      for (const auto& e : tc.children(child))
        out[tc.attribute("name").value()].push_back(e.attribute("message").value());
    }
  }
  return out;
}

/// A baseline of the fixture (`gate --update`), with H_p/M/Q4/AL/ss's sigma_c scaled by
/// 1 + 1e-3 (a drift a thousand times the default tolerance of 1e-6), and H_p/F/Q4/MPC/ss, which
/// did not converge in the fixture, recorded as converged (so that it stopped converging).
fs::path drifted_baseline(const TempDir& tmp) {
  const fs::path baseline = tmp.path() / "baseline.json";
  const auto r = run_cli(
      {"gate", "--update", "--baseline", baseline.string(), "--results", kFixture.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  auto doc = nlohmann::json::parse(read_text(baseline));
  bool drifted = false;
  for (auto& c : doc["cases"]) {
    if (c["id"] == "H_p/M/Q4/AL/ss") {
      c["quantities"]["sigma_c"]["value"] =
          c["quantities"]["sigma_c"]["value"].get<double>() * 1.001;
      drifted = true;
    }
    if (c["id"] == "H_p/F/Q4/MPC/ss") {
      c["status"] = "converged";
      c["reason"] = "";
    }
  }
  EXPECT_TRUE(drifted);
  write_text(baseline, doc.dump(2));
  return baseline;
}

// Requirement: against a baseline with one value drifted, the gate's JUnit file validates and
// fails exactly that value's row, its failure naming the value, the baseline and the tolerance;
// the rows of a case that stopped converging are errors; the XML and the summary equal their
// gold files.
TEST(JunitCli, DriftedBaselineFailsExactlyItsRow) {
  TempDir tmp;
  const fs::path baseline = drifted_baseline(tmp);
  const fs::path xml = tmp.path() / "gate.xml";
  const fs::path md = tmp.path() / "summary.md";
  const auto r = run_cli({"gate", "--baseline", baseline.string(), "--results", kFixture.string(),
                          "--junit", xml.string(), "--summary", md.string()});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  std::string log;
  EXPECT_TRUE(validates(xml, log)) << log;

  const auto failed = testcases_with(xml, "failure");
  ASSERT_EQ(failed.size(), 1u);
  ASSERT_EQ(failed.count("H_p/Q4/AL/ss/sigma_c"), 1u);
  const auto& reasons = failed.at("H_p/Q4/AL/ss/sigma_c");
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_NE(reasons[0].find("value drift of H_p/M/Q4/AL/ss sigma_c: now "), std::string::npos)
      << reasons[0];
  EXPECT_NE(reasons[0].find("> tolerance 1e-06"), std::string::npos) << reasons[0];
  const auto errors = testcases_with(xml, "error");
  ASSERT_EQ(errors.size(), 2u);
  for (const auto* row : {"H_p/Q4/MPC/ss/sigma_c", "H_p/Q4/MPC/ss/sigma_h"}) {
    ASSERT_EQ(errors.count(row), 1u) << row;
    EXPECT_NE(errors.at(row).at(0).find("status of H_p/F/Q4/MPC/ss: now not_converged, baseline "
                                        "converged"),
              std::string::npos)
        << errors.at(row).at(0);
  }

  expect_gold(read_text(xml), "gate_drifted.junit.xml");
  expect_gold(read_text(md), "gate_drifted.summary.md");
}

// Requirement: the gate of results against their own baseline passes every row (the fixture's
// failed and unconverged cases failed in the baseline too), and the XML validates.
TEST(JunitCli, UnchangedResultsPass) {
  TempDir tmp;
  const fs::path baseline = fixture_baseline(tmp.path());
  const fs::path xml = tmp.path() / "gate.xml";
  const auto r = run_cli({"gate", "--baseline", baseline.string(), "--results", kFixture.string(),
                          "--junit", xml.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::string log;
  EXPECT_TRUE(validates(xml, log)) << log;
  EXPECT_TRUE(testcases_with(xml, "failure").empty());
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(xml.c_str()));
  const auto root = doc.child("testsuites");
  EXPECT_EQ(root.attribute("tests").as_int(), 32);  // the fixture's rows
  EXPECT_EQ(root.attribute("failures").as_int(), 0);
  EXPECT_EQ(root.attribute("errors").as_int(), 0);
}

// Requirement: `run --junit` writes one testcase per row, with an error for each row whose case
// did not converge, and the file validates.
TEST(JunitCli, RunWritesAValidFile) {
  TempDir tmp;
  const fs::path xml = tmp.path() / "run.xml";
  const fs::path md = tmp.path() / "summary.md";
  const auto r = run_cli({"run",     "--problems",  "P_p,H_p",   "--meshes",
                          "C",       "--elements",  "Q4",        "--algorithms",
                          "AL",      "--contacts",  "ss",        "--jobs",
                          "1",       "--no-report", "--out",     (tmp.path() / "run").string(),
                          "--junit", xml.string(),  "--summary", md.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string log;
  EXPECT_TRUE(validates(xml, log)) << log;
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(xml.c_str()));
  std::set<std::string> names;
  for (const auto& suite : doc.child("testsuites").children("testsuite")) {
    for (const auto& tc : suite.children("testcase")) {
      names.insert(tc.attribute("name").value());
      EXPECT_STREQ(tc.attribute("classname").value(), suite.attribute("name").value());
      EXPECT_GT(tc.attribute("time").as_double(), 0.0);
    }
  }
  EXPECT_EQ(names,
            (std::set<std::string>{"P_p/Q4/AL/ss/sigma_z_max", "H_p/Q4/AL/ss/sigma_c",
                                   "H_p/Q4/AL/ss/contact_half_width", "H_p/Q4/AL/ss/sigma_h"}));
  EXPECT_NE(read_text(md).find("## contact-suite run (2 cases): passed"), std::string::npos)
      << read_text(md);
}

// Requirement: a --junit or --summary path that cannot be written is bad input (exit 2, one
// line naming it) refused before anything is read or run: no output directory appears.
TEST(JunitCli, UnwritablePathIsRefusedBeforeTheRun) {
  TempDir tmp;
  const std::string bad = (tmp.path() / "no-such-dir" / "junit.xml").string();
  auto r =
      run_cli({"run", "--problems", "P_p", "--meshes", "C", "--elements", "Q4", "--algorithms",
               "AL", "--contacts", "ss", "--out", (tmp.path() / "run").string(), "--junit", bad});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--junit " + bad + ": the directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_FALSE(fs::exists(tmp.path() / "run"));

  // The gate checks the path before it reads its (here missing) files.
  r = run_cli({"gate", "--baseline", "missing.json", "--results", "missing.json", "--summary",
               tmp.path().string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
}

// Requirement: --junit replaces only a file contact-suite wrote. A file of the user's at that
// path is refused (exit 2, one line naming it) before anything is read or run, and left as it
// was; the gate's own file from an earlier run is replaced. Fails if the user's file is
// overwritten, or if a rerun onto the tool's own file is refused.
TEST(JunitCli, ReplacesOnlyAFileItWrote) {
  TempDir tmp;
  const fs::path baseline = fixture_baseline(tmp.path());
  const fs::path xml = tmp.path() / "gate.xml";
  const auto gate = [&] {
    return run_cli({"gate", "--baseline", baseline.string(), "--results", kFixture.string(),
                    "--junit", xml.string()});
  };
  { std::ofstream(xml) << "<notes>the user's</notes>\n"; }
  auto r = gate();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--junit " + xml.string() + ": the file exists and contact-suite did not"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_EQ(read_text(xml), "<notes>the user's</notes>\n");

  fs::remove(xml);
  ASSERT_EQ(gate().exit_code, 0);
  const std::string first = read_text(xml);
  r = gate();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(xml), first);
  // A file an earlier version wrote (its root element, no mark) is the tool's too.
  std::string older = first;
  older.erase(older.find("<!--"), older.find("-->") + 4 - older.find("<!--"));
  std::ofstream(xml) << older;
  r = gate();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(xml), first);

  // A run refuses the user's file before it makes its output directory.
  fs::remove(xml);
  fs::create_symlink(baseline, xml);  // a link is replaced by nothing the tool wrote
  r = run_cli({"run", "--problems", "P_p", "--meshes", "C", "--elements", "Q4", "--algorithms",
               "AL", "--contacts", "ss", "--out", (tmp.path() / "run").string(), "--junit",
               xml.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("did not write it"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_symlink(xml));
  EXPECT_FALSE(fs::exists(tmp.path() / "run"));

  // A dangling link is the user's too: neither it nor its target is touched.
  fs::remove(xml);
  fs::create_symlink(tmp.path() / "nowhere.xml", xml);
  r = gate();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(fs::is_symlink(xml));
  EXPECT_FALSE(fs::exists(tmp.path() / "nowhere.xml"));

  // So at --summary (appended to, so a user's regular file is kept and added to): a dangling
  // link there was deleted by the writability probe, its target created.
  const fs::path summary = tmp.path() / "summary.md";
  fs::create_symlink(tmp.path() / "missing.md", summary);
  r = run_cli({"gate", "--baseline", baseline.string(), "--results", kFixture.string(), "--summary",
               summary.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a link to a missing file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_symlink(summary));
  EXPECT_FALSE(fs::exists(tmp.path() / "missing.md"));
}

}  // namespace
}  // namespace cs::apps

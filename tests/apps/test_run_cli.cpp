// `contact-suite run` end to end: a case matrix with both nodal stress recoveries, the command
// line recorded in results.json, and a bad recovery name rejected as bad input.

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"

namespace cs::apps {
namespace {

using testing::read_text;
using testing::run_cli;
using testing::TempDir;

// Requirement: --recovery spr,extrapolated grades every analysis both ways (the contact
// pressure, from the one contact solution, is the same), and results.json records the command
// line as typed.
TEST(RunCli, BothRecoveriesAndTheCommandLine) {
  TempDir tmp;
  const std::string out = (tmp.path() / "run").string();
  const std::vector<std::string> args{"run",
                                      "--problems",
                                      "H_p",
                                      "--meshes",
                                      "C",
                                      "--elements",
                                      "Q4",
                                      "--algorithms",
                                      "LMP",
                                      "--contacts",
                                      "ss",
                                      "--recovery",
                                      "spr,extrapolated",
                                      "--jobs",
                                      "1",
                                      "--out",
                                      out,
                                      "--no-report"};
  const auto r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(read_text(tmp.path() / "run" / "results.json"));
  ASSERT_EQ(doc["cases"].size(), 2u);
  EXPECT_EQ(doc["cases"][0]["id"], "H_p/C/Q4/LMP/ss");
  EXPECT_EQ(doc["cases"][1]["id"], "H_p/C/Q4/LMP/ss/extrapolated");
  EXPECT_EQ(doc["cases"][1]["recovery"], "extrapolated");
  const auto& a = doc["cases"][0]["quantities"]["sigma_c"];
  const auto& b = doc["cases"][1]["quantities"]["sigma_c"];
  EXPECT_EQ(a["contact_pressure"], b["contact_pressure"]);
  EXPECT_NE(a["value"], b["value"]);
  const std::string line = doc["run"]["command_line"];
  EXPECT_NE(line.find("run --problems H_p"), std::string::npos) << line;
  EXPECT_NE(line.find("--recovery spr,extrapolated"), std::string::npos) << line;
}

// Requirement: an unknown recovery is bad input: exit 2, one line naming it, nothing written.
TEST(RunCli, UnknownRecoveryIsBadInput) {
  TempDir tmp;
  const auto r = run_cli({"run", "--problems", "P_p", "--recovery", "smoothed", "--out",
                          (tmp.path() / "run").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown stress recovery 'smoothed'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "run"));
}

}  // namespace
}  // namespace cs::apps

// A run spread over shards and merged equals the run done at once: `run --shard K/3` for
// K = 1..3 over the C and M meshes of P_p and H_p, then `merge`, gives the unsharded run's
// cases and rows, value for value.

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

const std::vector<std::string> kSelection{"--problems", "P_p,H_p", "--meshes",   "C,M",
                                          "--jobs",     "1",       "--no-report"};

json run_into(const std::string& out, const std::vector<std::string>& extra) {
  std::vector<std::string> args{"run"};
  args.insert(args.end(), kSelection.begin(), kSelection.end());
  args.insert(args.end(), extra.begin(), extra.end());
  args.insert(args.end(), {"--out", out});
  const auto r = run_cli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return json::parse(read_text(out + "/results.json"));
}

/// A case without what legitimately differs between two runs: its timings and memory.
json without_timings(json c) {
  c.erase("wall_seconds");
  c.erase("peak_rss_mb");
  return c;
}

// Requirement: three slices merged equal the unsharded run in every case (status, iterations,
// sizes, every graded value, profile) and every row verdict, in the same order.
TEST(ShardMergeCli, ThreeShardsMergedEqualTheUnshardedRun) {
  TempDir tmp;
  const std::string dir = tmp.path().string();
  const json whole = run_into(dir + "/whole", {});
  std::vector<std::string> merge{"merge", dir + "/merged", "--no-report"};
  std::size_t sliced_cases = 0;
  for (int k = 1; k <= 3; ++k) {
    const std::string out = dir + "/shard" + std::to_string(k);
    const json slice = run_into(out, {"--shard", std::to_string(k) + "/3"});
    sliced_cases += slice["cases"].size();
    EXPECT_LT(slice["cases"].size(), whole["cases"].size()) << "slice " << k << " is everything";
    merge.push_back(out + "/results.json");
  }
  EXPECT_EQ(sliced_cases, whole["cases"].size());  // no case twice, none left out
  const auto r = run_cli(merge);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json merged = json::parse(read_text(dir + "/merged/results.json"));

  ASSERT_EQ(merged["cases"].size(), whole["cases"].size());
  for (std::size_t i = 0; i < whole["cases"].size(); ++i) {
    EXPECT_EQ(without_timings(merged["cases"][i]), without_timings(whole["cases"][i]))
        << whole["cases"][i]["id"];
  }
  ASSERT_EQ(merged["rows"].size(), whole["rows"].size());
  for (std::size_t i = 0; i < whole["rows"].size(); ++i)
    EXPECT_EQ(merged["rows"][i], whole["rows"][i]) << whole["rows"][i]["id"];
  EXPECT_EQ(merged["problems"], whole["problems"]);
}

}  // namespace
}  // namespace cs::apps

// Requirement: `run --shard K/N` slices are a partition of the case list (every case in exactly
// one slice, the cases of one model together, the same on every machine), and `merge` refuses
// slices of different runs, a slice given twice, a missing slice (named) and overlapping cases.

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "suites/case_matrix.hpp"
#include "suites/results_merge.hpp"
#include "suites/runner.hpp"
#include "suites/shard.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

std::vector<CaseSpec> matrix() {
  CaseSelection sel;
  sel.problems = {ProblemId::P_p, ProblemId::H_p, ProblemId::S_1};
  sel.meshes = {MeshLevel::C, MeshLevel::M};
  return make_case_matrix(sel);
}

double cost(const CaseSpec& s) {
  return s.mesh == MeshLevel::M ? 4.0 : 1.0;
}

TEST(Shard, SlicesPartitionTheCasesAndKeepModelsTogether) {
  const auto all = matrix();
  std::map<std::string, int> slice_of_case, slice_of_model;
  std::vector<double> load(3, 0.0);
  for (int k = 1; k <= 3; ++k) {
    for (const auto& c : shard_cases(all, {k, 3}, cost)) {
      EXPECT_TRUE(slice_of_case.emplace(case_id(c), k).second) << case_id(c) << " twice";
      const auto [it, inserted] = slice_of_model.emplace(model_key(c), k);
      EXPECT_EQ(it->second, k) << model_key(c) << " split across slices";
      if (inserted)
        load[k - 1] += cost(c);
    }
  }
  EXPECT_EQ(slice_of_case.size(), all.size());
  // Balanced by cost: 12 models (6 of cost 4, 6 of cost 1) over 3 slices, 10 each.
  for (double l : load)
    EXPECT_EQ(l, 10.0);
  EXPECT_EQ(shard_cases(all, {2, 3}, cost), shard_cases(all, {2, 3}, cost));  // deterministic
}

TEST(Shard, BadSliceSpecificationsAreRejected) {
  EXPECT_EQ(parse_shard("2/8").index, 2);
  for (const char* bad : {"0/3", "4/3", "a/b", "3", "1/0", "/3", "1/", "-1/3", "1/3x", ""})
    EXPECT_THROW(parse_shard(bad), SuiteInputError) << bad;
}

schema::ResultsDocument slice(const std::vector<CaseSpec>& all, int k, int n,
                              const std::string& key) {
  schema::ResultsDocument d;
  d.source = "slice" + std::to_string(k);
  d.run.environment = {{"contact_suite_version", "1"}};
  d.run.shard = schema::ShardInfo{k, n, key, static_cast<long long>(all.size())};
  for (const auto& spec : shard_cases(all, {k, n}, cost)) {
    CaseResult c;
    c.spec = spec;
    c.status = CaseStatus::converged;
    d.cases.push_back(c);
  }
  return d;
}

TEST(Merge, SlicesOfOneRunMergeIntoTheCasesInBatteryOrder) {
  const auto all = matrix();
  const auto merged =
      merge_results({slice(all, 3, 3, "k"), slice(all, 1, 3, "k"), slice(all, 2, 3, "k")}, "m");
  ASSERT_EQ(merged.cases.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    EXPECT_EQ(case_id(merged.cases[i].spec), case_id(all[i]));
  EXPECT_FALSE(merged.run.shard.has_value());
  EXPECT_EQ(merged.problems.size(), 3u);
}

// Requirement: a merged run records how many files it came from, its wall time summed over them
// (machine time, since the parts may have run one after another) and the most workers any one
// part had, not their sum: 3 slices of 2 workers are not a 6-worker run.
TEST(Merge, RecordsThePartsMachineTimeAndTheirWorkers) {
  const auto all = matrix();
  std::vector<schema::ResultsDocument> parts;
  for (int k = 1; k <= 3; ++k) {
    parts.push_back(slice(all, k, 3, "k"));
    parts.back().run.wall_seconds = 10.0 * k;
    parts.back().run.jobs = 2;
  }
  parts[1].run.jobs = 1;
  const auto merged = merge_results(parts, "m");
  EXPECT_EQ(merged.run.merged_files, 3);
  EXPECT_EQ(merged.run.jobs, 2);
  EXPECT_DOUBLE_EQ(merged.run.wall_seconds, 60.0);
}

// Requirement: files of different builds merge only when asked (`--mixed-builds`), and the
// merged run then names each build with its number of files instead of the first one's.
TEST(Merge, MixedBuildsAreRecordedWhenAllowed) {
  const auto all = matrix();
  auto a = slice(all, 1, 3, "k"), b = slice(all, 2, 3, "k"), c = slice(all, 3, 3, "k");
  b.run.environment["contact_suite_version"] = "2";
  EXPECT_THROW(merge_results({a, b, c}, "m"), SuiteInputError);
  const auto merged = merge_results({a, b, c}, "m", BuildMix::record);
  EXPECT_EQ(merged.run.environment["contact_suite_version"], "mixed: 1 (2 files), 2 (1 file)");
  EXPECT_EQ(merged.cases.size(), all.size());
  b.run.environment["contact_suite_version"] = "1";
  EXPECT_EQ(merge_results({a, b, c}, "m").run.environment["contact_suite_version"], "1");
  // Files that record no build are merged as they are: no version is made up for them.
  for (auto* d : {&a, &b, &c})
    d->run.environment.erase("contact_suite_version");
  EXPECT_FALSE(merge_results({a, b, c}, "m").run.environment.contains("contact_suite_version"));
}

void expect_refused(const std::vector<schema::ResultsDocument>& parts, const std::string& needle) {
  try {
    merge_results(parts, "m");
    ADD_FAILURE() << "merged; expected: " << needle;
  } catch (const SuiteInputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(Merge, RefusesMissingOverlappingAndForeignSlices) {
  const auto all = matrix();
  expect_refused({slice(all, 1, 3, "k"), slice(all, 3, 3, "k")}, "slice 2/3 is missing");
  expect_refused({slice(all, 1, 3, "k"), slice(all, 1, 3, "k"), slice(all, 2, 3, "k")},
                 "slice 1/3 is given twice");
  expect_refused({slice(all, 1, 3, "k"), slice(all, 2, 3, "other"), slice(all, 3, 3, "k")},
                 "slices of different runs");
  auto other_build = slice(all, 2, 3, "k");
  other_build.run.environment["contact_suite_version"] = "2";
  expect_refused({slice(all, 1, 3, "k"), other_build, slice(all, 3, 3, "k")}, "different builds");
  auto unsharded = slice(all, 1, 1, "u");
  unsharded.run.shard.reset();
  expect_refused({slice(all, 1, 3, "k"), unsharded}, "mix a slice with unsharded results");
  auto a = slice(all, 1, 1, "u"), b = slice(all, 1, 1, "u");
  a.run.shard.reset();
  b.run.shard.reset();
  expect_refused({a, b}, "is in more than one file");
  expect_refused({}, "no results files");
}

}  // namespace
}  // namespace cs::suites

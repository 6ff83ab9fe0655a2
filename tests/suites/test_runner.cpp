// The engine with a fake executor: order, sharing of a model within a group, failures kept
// as results, the same results with one or two workers.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "platform/available_cores.hpp"
#include "solver/spare_cores.hpp"
#include "suites/case_matrix.hpp"
#include "suites/runner.hpp"

namespace cs::suites {
namespace {

/// A model "built" once per group; each case's value is a deterministic function of its spec.
class FakeExecutor : public GroupExecutor {
 public:
  explicit FakeExecutor(const CaseSpec& representative) : key_(model_key(representative)) {}
  CaseResult run(const CaseSpec& spec) override {
    if (spec.algorithm == Algorithm::MPC && spec.problem == ProblemId::H_p) {
      throw std::runtime_error("forced failure");
    }
    EXPECT_EQ(model_key(spec), key_);  // only cases of this model come here
    CaseResult r;
    r.status = CaseStatus::converged;
    QuantityResult q;
    q.quantity = Quantity::sigma_c;
    q.value = static_cast<double>(case_id(spec).size()) + static_cast<int>(spec.algorithm);
    r.quantities.push_back(q);
    return r;
  }

 private:
  std::string key_;
};

std::vector<CaseSpec> small_matrix() {
  CaseSelection sel;
  sel.problems = {ProblemId::H_p, ProblemId::S_1};
  sel.meshes = {MeshLevel::C, MeshLevel::M};
  return make_case_matrix(sel);  // 2 x 2 x 2 elements x 5 algorithms x 2 contacts = 80
}

TEST(CaseMatrix, FullStudyMatrixHas660Cases) {
  EXPECT_EQ(make_case_matrix({}).size(), 660u);
  CaseSelection sel;
  sel.contacts = {ContactKind::mortar, ContactKind::mortar};  // duplicates ignored
  EXPECT_EQ(make_case_matrix(sel).size(), 330u);
}

TEST(CaseMatrix, RecoveriesAreTheInnermostAxis) {
  CaseSelection sel;
  EXPECT_EQ(make_case_matrix(sel).front().recovery, Recovery::spr);
  sel.recoveries = {Recovery::spr, Recovery::extrapolated};
  const auto cases = make_case_matrix(sel);
  ASSERT_EQ(cases.size(), 1320u);
  EXPECT_EQ(cases[0].recovery, Recovery::spr);
  EXPECT_EQ(cases[1].recovery, Recovery::extrapolated);
  CaseSpec first = cases[1];
  first.recovery = Recovery::spr;
  EXPECT_EQ(case_id(first), case_id(cases[0]));  // the same analysis, recovered two ways
}

TEST(Runner, SharesOneModelPerGroupAndKeepsOrder) {
  const auto cases = small_matrix();
  ASSERT_EQ(cases.size(), 80u);
  std::atomic<int> builds{0};
  auto factory = [&](const CaseSpec& s) {
    ++builds;
    return std::make_unique<FakeExecutor>(s);
  };
  int reported = 0;
  RunnerOptions options;
  options.jobs = 2;
  options.on_case_done = [&](const CaseResult&) { ++reported; };
  const auto results = run_cases(cases, factory, options);
  EXPECT_EQ(builds.load(), 8);  // 2 problems x 2 meshes x 2 elements
  EXPECT_EQ(reported, 80);
  ASSERT_EQ(results.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(case_id(results[i].spec), case_id(cases[i]));
  }
}

TEST(Runner, FailuresBecomeResultsAndTheRunGoesOn) {
  const auto cases = small_matrix();
  auto factory = [](const CaseSpec& s) -> std::unique_ptr<GroupExecutor> {
    if (s.problem == ProblemId::S_1 && s.mesh == MeshLevel::M && s.element == Element::Q8) {
      throw std::invalid_argument("mesh too coarse for the contact width");
    }
    return std::make_unique<FakeExecutor>(s);
  };
  const auto results = run_cases(cases, factory, {});
  int failed = 0, converged = 0;
  for (const auto& r : results) {
    if (r.status == CaseStatus::failed) {
      ++failed;
      EXPECT_FALSE(r.reason.empty());
    } else {
      ++converged;
    }
  }
  EXPECT_EQ(failed, 10 + 8);  // one whole group (10) + H_p MPC (2 meshes x 2 elements x 2)
  EXPECT_EQ(converged, 80 - failed);
}

TEST(Runner, OneAndTwoWorkersGiveTheSameResults) {
  const auto cases = small_matrix();
  auto factory = [](const CaseSpec& s) { return std::make_unique<FakeExecutor>(s); };
  RunnerOptions one, two;
  one.jobs = 1;
  two.jobs = 2;
  two.group_cost = [](const CaseSpec& s) { return s.mesh == MeshLevel::M ? 4.0 : 1.0; };
  const auto a = run_cases(cases, factory, one);
  const auto b = run_cases(cases, factory, two);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].status, b[i].status);
    if (!a[i].quantities.empty()) {
      EXPECT_EQ(a[i].quantities[0].value, b[i].quantities[0].value);
    }
  }
}

/// Counts how many "big" groups (mesh M) run at once; each case takes a few milliseconds so
/// that groups overlap when the schedule lets them.
class OverlapExecutor : public GroupExecutor {
 public:
  OverlapExecutor(const CaseSpec& representative, std::atomic<int>& running, std::atomic<int>& most)
      : big_(representative.mesh == MeshLevel::M), running_(running), most_(most) {
    if (big_)
      most_ = std::max(most_.load(), ++running_);
  }
  ~OverlapExecutor() override {
    if (big_)
      --running_;
  }
  CaseResult run(const CaseSpec&) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    CaseResult r;
    r.status = CaseStatus::converged;
    return r;
  }

 private:
  bool big_;
  std::atomic<int>& running_;
  std::atomic<int>& most_;
};

// Requirement (issue 12): a memory-aware schedule never runs the two largest models at once,
// yet runs small ones beside a large one; without a budget the large ones do overlap.
TEST(Runner, MemoryBudgetKeepsTheLargestModelsApart) {
  const auto cases = small_matrix();  // 8 models: 4 on M (memory 10), 4 on C (memory 1)
  auto memory = [](const CaseSpec& s) { return s.mesh == MeshLevel::M ? 10.0 : 1.0; };
  for (const double budget : {15.0, 0.0}) {
    std::atomic<int> running{0}, most{0};
    RunnerOptions options;
    options.jobs = 2;
    options.group_cost = memory;
    options.group_memory = memory;
    options.memory_budget = budget;
    const auto results = run_cases(
        cases,
        [&](const CaseSpec& s) { return std::make_unique<OverlapExecutor>(s, running, most); },
        options);
    for (const auto& r : results)
      EXPECT_EQ(r.status, CaseStatus::converged);
    EXPECT_EQ(most.load(), budget > 0 ? 1 : 2) << "budget " << budget;
  }
}

/// Records, at each case, by how much the cores the run has lent (solver/spare_cores.hpp)
/// exceed those the models being run leave idle.
class LendingExecutor : public GroupExecutor {
 public:
  LendingExecutor(const CaseSpec& representative, std::atomic<int>& running,
                  std::atomic<int>& most_over_cores, int cores)
      : running_(running),
        most_(most_over_cores),
        cores_(cores),
        case_time_(1 + std::hash<std::string>{}(model_key(representative)) % 6) {
    ++running_;
  }
  ~LendingExecutor() override { --running_; }
  CaseResult run(const CaseSpec&) override {
    const int over = solver::spare_cores() - std::max(0, cores_ - running_.load());
    most_ = std::max(most_.load(), over);
    std::this_thread::sleep_for(std::chrono::milliseconds(case_time_));
    CaseResult r;
    r.status = CaseStatus::converged;
    return r;
  }

 private:
  std::atomic<int>& running_;
  std::atomic<int>& most_;
  int cores_;
  long case_time_;  ///< ms; models of unlike lengths, so that workers finish one by one
};

// Requirement: a run lends the cores its workers leave idle, never one a worker still needs:
// never more than the cores less the models running, with --jobs at one, at the core count and
// above it (a finished worker's core is lent only once fewer workers than cores are left);
// every core is taken back when the run ends.
TEST(Runner, LendsOnlyTheCoresNoWorkerNeeds) {
  const int cores = platform::available_cores();
  const auto cases = small_matrix();  // 8 models of 10 cases
  for (const int jobs : {1, cores, cores + 2}) {
    std::atomic<int> running{0}, most{-cores};
    RunnerOptions options;
    options.jobs = jobs;
    options.group_cost = [](const CaseSpec& s) { return s.mesh == MeshLevel::M ? 3.0 : 1.0; };
    run_cases(
        cases,
        [&](const CaseSpec& s) {
          return std::make_unique<LendingExecutor>(s, running, most, cores);
        },
        options);
    EXPECT_LE(most.load(), 0) << "jobs " << jobs;
    EXPECT_EQ(solver::spare_cores(), 0) << "jobs " << jobs;
  }
  std::atomic<int> running{0}, most{-cores};
  RunnerOptions one;
  one.jobs = 1;
  run_cases(
      cases,
      [&](const CaseSpec& s) { return std::make_unique<LendingExecutor>(s, running, most, cores); },
      one);
  EXPECT_EQ(most.load(), 0);  // one worker: the other cores are lent throughout
}

TEST(Runner, ContactOnlyParametersShareTheModel) {
  CaseSpec a, b;
  b.overrides["fkn"] = 10;
  b.algorithm = Algorithm::PM;
  EXPECT_EQ(model_key(a), model_key(b));
  b.recovery = Recovery::extrapolated;  // post-processing only
  EXPECT_EQ(model_key(a), model_key(b));
  b.overrides["nu"] = 0.3;
  EXPECT_NE(model_key(a), model_key(b));
}

}  // namespace
}  // namespace cs::suites

#include <cstdio>

#include "suites/progress.hpp"

namespace cs::suites {
namespace {

std::string report_of(bool interactive) {
  std::FILE* f = std::tmpfile();
  ProgressReporter p(2, f, interactive);
  CaseResult ok;
  ok.status = CaseStatus::converged;
  CaseResult bad;
  bad.status = CaseStatus::failed;
  bad.reason = "singular system";
  p.case_done(ok);
  p.case_done(bad);
  p.finish();
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;)
    text += static_cast<char>(c);
  std::fclose(f);
  return text;
}

TEST(Progress, PlainLinesWhenNotATerminal) {
  const std::string text = report_of(false);
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_NE(text.find("[1/2]"), std::string::npos);
  EXPECT_NE(text.find("(singular system)"), std::string::npos);
  EXPECT_NE(text.find("2 cases in"), std::string::npos);
  EXPECT_NE(text.find("1 converged, 0 not converged, 1 failed"), std::string::npos);
}

TEST(Progress, BarWithCountsAndEtaOnATerminal) {
  const std::string text = report_of(true);
  EXPECT_NE(text.find('\r'), std::string::npos);
  EXPECT_NE(text.find("[###############...............] 1/2"), std::string::npos) << text;
  EXPECT_NE(text.find("ETA"), std::string::npos);
}

TEST(Progress, Durations) {
  EXPECT_EQ(ProgressReporter::format_duration(5.2), "5 s");
  EXPECT_EQ(ProgressReporter::format_duration(125), "2:05");
  EXPECT_EQ(ProgressReporter::format_duration(3725), "1:02:05");
  EXPECT_EQ(ProgressReporter::format_duration(NAN), "?");
}

}  // namespace
}  // namespace cs::suites

// Requirement: a ccx run is classified from its exit and its own messages: converged after
// "Job finished"; not converged with ccx's reason when its increment control gives up; failed
// with ccx's first *ERROR message (one line) when it rejects the input, or with what happened
// when it cannot start or dies; timeout at the time limit. The .sta gives increments and
// iterations. (Texts below are ccx 2.20's own, from runs of this adapter.)

#include <signal.h>

#include <gtest/gtest.h>

#include "adapters/calculix/run_status.hpp"

namespace cs::adapters::calculix {
namespace {

platform::ChildResult exited(int code) {
  platform::ChildResult child;
  child.started = true;
  child.exit_code = code;
  return child;
}

constexpr const char* kFinished =
    " STEP            1\n\n Static analysis was selected\n\n Job finished\n\n"
    "________________________________________\n\nTotal CalculiX Time: 0.034218\n";

constexpr const char* kCutbacks =
    " Newton-Raphson iterative procedure is active\n\n"
    " divergence; the increment size is decreased to 2.441406e-04\n"
    " the increment is reattempted\n\n\n"
    " *ERROR: too many cutbacks\n"
    " best solution and residuals are in the frd file\n\n";

constexpr const char* kRejected =
    " *WARNING reading *STATIC: a nonlinear analysis is requested\n"
    "          but no time increment nor step is specified\n\n"
    " *ERROR reading *FRICTION: friction coefficient\n"
    "        must be strictly positive\n"
    " *ERROR reading *FRICTION. Card image:\n"
    "        0.0,1.0E6\n\n"
    " *ERROR in calinput: at least one fatal\n";

TEST(CalculixStatus, ConvergedRun) {
  const RunOutcome r = classify_run(exited(0), kFinished);
  EXPECT_EQ(r.status, CalculixStatus::Converged);
  EXPECT_EQ(r.reason, "");
}

TEST(CalculixStatus, CutbacksAreNotConvergedWithCcxReason) {
  const RunOutcome r = classify_run(exited(201), kCutbacks);
  EXPECT_EQ(r.status, CalculixStatus::NotConverged);
  EXPECT_EQ(r.reason, "*ERROR: too many cutbacks");
  EXPECT_EQ(classify_run(exited(201), " *ERROR: increment size smaller than minimum\n").status,
            CalculixStatus::NotConverged);
}

TEST(CalculixStatus, RejectedInputFailsWithTheFirstMessageOnOneLine) {
  const RunOutcome r = classify_run(exited(201), kRejected);
  EXPECT_EQ(r.status, CalculixStatus::Failed);
  EXPECT_EQ(r.reason, "*ERROR reading *FRICTION: friction coefficient must be strictly positive");
  EXPECT_EQ(first_error_message(kFinished), "");
  const std::string long_message = " *ERROR: " + std::string(1000, 'x') + "\n";
  EXPECT_LE(first_error_message(long_message).size(), 300u);
}

TEST(CalculixStatus, ChildFailures) {
  platform::ChildResult missing;
  missing.spawn_error = "cannot run 'ccx': program not found in PATH";
  EXPECT_EQ(classify_run(missing, "").status, CalculixStatus::Failed);
  EXPECT_EQ(classify_run(missing, "").reason, missing.spawn_error);

  platform::ChildResult crashed = exited(-1);
  crashed.signal = SIGSEGV;
  const RunOutcome c = classify_run(crashed, kFinished);
  EXPECT_EQ(c.status, CalculixStatus::Failed);
  EXPECT_NE(c.reason.find("signal 11"), std::string::npos) << c.reason;

  platform::ChildResult slow = exited(-1);
  slow.signal = SIGTERM;
  slow.timed_out = true;
  EXPECT_EQ(classify_run(slow, "").status, CalculixStatus::Timeout);

  platform::ChildResult interrupted = exited(-1);
  interrupted.signal = SIGINT;
  interrupted.interrupted = true;
  EXPECT_EQ(classify_run(interrupted, "").status, CalculixStatus::Failed);
  EXPECT_NE(classify_run(interrupted, "").reason.find("interrupted"), std::string::npos);

  // A non-zero exit without a message, or an exit 0 without "Job finished": failed.
  EXPECT_EQ(classify_run(exited(3), "").status, CalculixStatus::Failed);
  EXPECT_EQ(classify_run(exited(0), " STEP 1\n").status, CalculixStatus::Failed);
}

TEST(CalculixStatus, StaRowsGiveIncrementsAndIterations) {
  const StaSummary sta = parse_sta(
      "SUMMARY OF JOB INFORMATION\n"
      "  STEP      INC     ATT  ITRS     TOT TIME     STEP TIME      INC TIME\n"
      "     1          1     1U    8  0.000000E+00  0.000000E+00  0.100000E+01\n"
      "     1          1     2U   11  0.000000E+00  0.000000E+00  0.250000E+00\n"
      "     1          1     3     7  0.250000E+00  0.250000E+00  0.250000E+00\n"
      "     1          2     1     4  0.100000E+01  0.100000E+01  0.750000E+00\n");
  EXPECT_EQ(sta.attempts, 4);
  EXPECT_EQ(sta.increments, 2);
  EXPECT_EQ(sta.iterations, 30);
  EXPECT_EQ(parse_sta("").attempts, 0);
  EXPECT_EQ(parse_sta("garbage\n1 2\n\xff\n").attempts, 0);
}

// Found by fuzz/sta_reader: a row with a negative count was counted, and the iterations went
// negative (the second line is the one of the fuzzer's input that did it). Seen while fixing it:
// iterations near INT_MAX overflowed the sum (undefined behaviour).
TEST(CalculixStatus, StaRowsWithCountsOutOfRangeAreNotRows) {
  const StaSummary negative = parse_sta(
      "     1          1     3U    7  0.0E+00\n"
      "     1   -03     1   -03       1 ---\n"
      "     1   -03          1     1  0.0E+00\n"
      "     1          1     1    -5  0.0E+00\n"
      "     0          1     1     5  0.0E+00\n"
      "     1          1    -1U    5  0.0E+00\n");
  EXPECT_EQ(negative.attempts, 1);
  EXPECT_EQ(negative.increments, 0);
  EXPECT_EQ(negative.iterations, 7);
  const StaSummary huge = parse_sta(
      "     1          1     1  2147483647  1.0\n"
      "     1          2     1  2147483647  1.0\n");
  EXPECT_EQ(huge.attempts, 2);
  EXPECT_EQ(huge.iterations, 2147483647);
}

TEST(CalculixStatus, Names) {
  EXPECT_STREQ(to_string(CalculixStatus::Converged), "converged");
  EXPECT_STREQ(to_string(CalculixStatus::NotConverged), "not converged");
  EXPECT_STREQ(to_string(CalculixStatus::Failed), "failed");
  EXPECT_STREQ(to_string(CalculixStatus::Timeout), "timeout");
}

}  // namespace
}  // namespace cs::adapters::calculix

// Requirement: after install_interrupt_forwarding(), SIGINT/SIGTERM received by this process
// is recorded and forwarded to running children, whose run_child returns promptly.

#include <signal.h>

#include <chrono>
#include <future>
#include <thread>

#include <gtest/gtest.h>

#include "platform/child_process.hpp"
#include "platform/interrupts.hpp"

namespace cs::platform {
namespace {

/// Installs forwarding for one test and restores everything afterwards.
class Interrupts : public ::testing::Test {
 protected:
  void SetUp() override {
    reset_interrupt_state_for_tests();
    install_interrupt_forwarding();
  }
  void TearDown() override {
    uninstall_interrupt_forwarding();
    reset_interrupt_state_for_tests();
  }
};

ChildResult sleep_in_background_and_interrupt(int sig, double* seconds_to_return) {
  ChildOptions options;
  options.argv = {"sleep", "30"};
  auto running = std::async(std::launch::async, [&] { return run_child(options); });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // let the child start
  const auto t0 = std::chrono::steady_clock::now();
  raise(sig);
  const ChildResult r = running.get();
  *seconds_to_return = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

TEST_F(Interrupts, NoneRecordedAtStart) {
  EXPECT_EQ(interrupted_signal(), 0);
}

TEST_F(Interrupts, SigintIsForwardedToTheChild) {
  double seconds = 0.0;
  const ChildResult r = sleep_in_background_and_interrupt(SIGINT, &seconds);
  EXPECT_EQ(interrupted_signal(), SIGINT);
  EXPECT_TRUE(r.started);
  EXPECT_TRUE(r.interrupted);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.signal, SIGINT);  // the forwarded signal killed sleep, not our SIGKILL
  EXPECT_LT(seconds, 2.0);      // polling interval + reaping (+ load); sleep wanted 30 s
}

TEST_F(Interrupts, SigtermIsForwardedToTheChild) {
  double seconds = 0.0;
  const ChildResult r = sleep_in_background_and_interrupt(SIGTERM, &seconds);
  EXPECT_EQ(interrupted_signal(), SIGTERM);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(r.signal, SIGTERM);
  EXPECT_LT(seconds, 2.0);  // idem
}

TEST_F(Interrupts, FirstSignalWinsAndResetClearsIt) {
  raise(SIGTERM);
  raise(SIGINT);
  EXPECT_EQ(interrupted_signal(), SIGTERM);
  reset_interrupt_state_for_tests();
  EXPECT_EQ(interrupted_signal(), 0);
}

TEST_F(Interrupts, NoChildStartsOnceInterrupted) {
  raise(SIGINT);
  ChildOptions options;
  options.argv = {"true"};
  const ChildResult r = run_child(options);
  EXPECT_FALSE(r.started);
  EXPECT_TRUE(r.interrupted);
  EXPECT_NE(r.spawn_error.find("interrupted"), std::string::npos);
}

TEST_F(Interrupts, ManyConcurrentChildrenAreAllStopped) {
  ChildOptions options;
  options.argv = {"sleep", "30"};
  std::vector<std::future<ChildResult>> running;
  for (int i = 0; i < 8; ++i)
    running.push_back(std::async(std::launch::async, [&] { return run_child(options); }));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto t0 = std::chrono::steady_clock::now();
  raise(SIGINT);
  for (auto& f : running) {
    const ChildResult r = f.get();
    EXPECT_TRUE(r.interrupted);
    EXPECT_EQ(r.signal, SIGINT);
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
}

}  // namespace
}  // namespace cs::platform

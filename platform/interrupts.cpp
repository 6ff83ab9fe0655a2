#include "platform/interrupts.hpp"

#include <signal.h>

#include <array>
#include <atomic>
#include <cerrno>

namespace cs::platform {
namespace {

static_assert(std::atomic<int>::is_always_lock_free, "the handler needs lock-free atomics");
static_assert(std::atomic<pid_t>::is_always_lock_free, "the handler needs lock-free atomics");

/// A slot holds 0 (free), -1 (reserved, child not started yet) or a process group id (> 0).
constexpr pid_t kFree = 0;
constexpr pid_t kReserved = -1;

std::array<std::atomic<pid_t>, kMaxChildGroups> g_groups{};
std::atomic<int> g_signal{0};
std::atomic<bool> g_installed{false};
struct sigaction g_previous_int {};
struct sigaction g_previous_term {};

/// Records the first interrupt and forwards it to every registered child group.
extern "C" void on_interrupt(int sig) {
  const int saved_errno = errno;
  int none = 0;
  g_signal.compare_exchange_strong(none, sig);
  for (auto& slot : g_groups) {
    const pid_t pgid = slot.load();
    if (pgid > 0)
      kill(-pgid, sig);
  }
  errno = saved_errno;
}

}  // namespace

void install_interrupt_forwarding() {
  if (g_installed.exchange(true))
    return;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

void uninstall_interrupt_forwarding() {
  if (!g_installed.exchange(false))
    return;
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int interrupted_signal() {
  return g_signal.load();
}

void reset_interrupt_state_for_tests() {
  g_signal.store(0);
}

int reserve_child_group_slot() {
  for (int i = 0; i < kMaxChildGroups; ++i) {
    pid_t expected = kFree;
    if (g_groups[i].compare_exchange_strong(expected, kReserved))
      return i;
  }
  return -1;
}

void set_child_group(int slot, pid_t pgid) {
  g_groups[slot].store(pgid);
}

void release_child_group_slot(int slot) {
  g_groups[slot].store(kFree);
}

}  // namespace cs::platform

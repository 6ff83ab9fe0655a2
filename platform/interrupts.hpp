#pragma once
// Interrupt forwarding: SIGINT and SIGTERM stop this process and its children together.
//
// Children started by run_child (platform/child_process.hpp) live in their own process groups,
// so a Ctrl-C at the terminal (SIGINT to our foreground group) does not reach them. Once
// install_interrupt_forwarding() has run, the handler
//   1. records the first signal received (interrupted_signal() returns it), and
//   2. sends the signal to the process group of every running child (a fixed-size, lock-free
//      registry of process group ids that run_child fills and empties).
// The handler does only async-signal-safe work (atomic loads and stores, kill()). It does not
// exit: callers poll interrupted_signal() between units of work, stop, clean up and exit with
// 128 + signal (130 for SIGINT, 143 for SIGTERM). A run_child in progress notices the signal
// within a few milliseconds, makes sure its child's group is dead and returns.

#include <sys/types.h>

namespace cs::platform {

/// Installs the SIGINT and SIGTERM handlers (idempotent; thread-safe to call from one thread at
/// start-up). The previous dispositions are kept for uninstall_interrupt_forwarding().
void install_interrupt_forwarding();

/// Restores the dispositions that install_interrupt_forwarding() replaced (for tests).
void uninstall_interrupt_forwarding();

/// The first SIGINT or SIGTERM received since start-up (or the last reset), 0 if none.
int interrupted_signal();

/// Forgets a recorded interrupt (for tests that raise one on purpose).
void reset_interrupt_state_for_tests();

/// The number of child process groups the registry can hold at once.
inline constexpr int kMaxChildGroups = 1024;

/// Reserves a registry slot before a child is started; returns its index, or -1 when all
/// kMaxChildGroups slots are taken.
int reserve_child_group_slot();

/// Stores the child's process group id in a reserved slot: from now on interrupts are forwarded
/// to it.
void set_child_group(int slot, pid_t pgid);

/// Empties a slot (call before reaping the child, while its group id cannot be reused).
void release_child_group_slot(int slot);

}  // namespace cs::platform

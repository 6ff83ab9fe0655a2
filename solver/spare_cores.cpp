#include "solver/spare_cores.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <system_error>
#include <thread>

namespace cs::solver {
namespace {

std::atomic<int>& pool() {
  static std::atomic<int> idle{0};
  return idle;
}

/// The OpenMP runtime's max-active-levels on the calling thread, or nothing when no OpenMP
/// runtime is loaded (the libraries load it, the solver does not link it).
std::optional<int> openmp_levels_here() {
  using GetFn = int (*)();
  const auto get = reinterpret_cast<GetFn>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  return get != nullptr ? std::optional<int>(get()) : std::nullopt;
}

void set_openmp_levels_here(std::optional<int> levels) {
  using SetFn = void (*)(int);
  const auto set = reinterpret_cast<SetFn>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  if (levels && set != nullptr)
    set(*levels);
}

}  // namespace

void lend_spare_cores(int n) {
  pool().fetch_add(n);
}

int spare_cores() {
  return std::max(0, pool().load());
}

SpareCore::SpareCore() {
  int now = pool().load();
  while (now > 0 && !pool().compare_exchange_weak(now, now - 1)) {
  }
  borrowed_ = now > 0;
}

SpareCore::~SpareCore() {
  if (borrowed_)
    pool().fetch_add(1);
}

void run_both(const std::function<void()>& first, const std::function<void()>& second) {
  const SpareCore core;
  std::exception_ptr failed;
  std::thread other;
  if (core) {
    const std::optional<int> levels = openmp_levels_here();
    try {
      other = std::thread([&, levels] {
        set_openmp_levels_here(levels);  // libgomp keeps the setting per thread
        try {
          second();
        } catch (...) {
          failed = std::current_exception();
        }
      });
    } catch (const std::system_error&) {  // no thread to be had: both here
    }
  }
  if (!other.joinable()) {
    first();
    second();
    return;
  }
  try {
    first();
  } catch (...) {
    other.join();
    throw;
  }
  other.join();
  if (failed)
    std::rethrow_exception(failed);
}

}  // namespace cs::solver

#include "solver/spare_cores.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <system_error>
#include <thread>

#include "solver/openmp_levels.hpp"

namespace cs::solver {
namespace {

std::atomic<int>& pool() {
  static std::atomic<int> idle{0};
  return idle;
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
    const std::optional<int> levels = openmp_active_levels();
    try {
      other = std::thread([&, levels] {
        if (levels)
          set_openmp_active_levels(*levels);  // libgomp keeps the setting per thread
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

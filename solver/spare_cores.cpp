#include "solver/spare_cores.hpp"

#include <algorithm>
#include <atomic>

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

}  // namespace cs::solver

#include "apps/memory_plan.hpp"

#include <fmt/format.h>

#include "apps/usage_error.hpp"

namespace cs::apps {
namespace {

double gib(double mib) {
  return mib / 1024.0;
}

/// The limit in MiB and the words that explain it; limit <= 0: none.
std::pair<double, std::string> memory_limit(const MemoryLimits& limits) {
  const double machine = limits.available_mib * (1.0 - kMemoryMargin);
  const std::string from_machine = fmt::format("MemAvailable {:.2f} GiB less a {:.0f} % margin",
                                               gib(limits.available_mib), 100.0 * kMemoryMargin);
  if (limits.max_mib > 0.0 && (machine <= 0.0 || limits.max_mib < machine))
    return {limits.max_mib, "--max-memory"};
  return {machine, from_machine};
}

}  // namespace

MemoryPlan plan_memory(double largest_mib, const std::string& largest_name,
                       const MemoryLimits& limits) {
  const auto [limit, why] = memory_limit(limits);
  if (limit <= 0.0)
    return {1.5 * largest_mib, {}};
  if (largest_mib > limit) {
    throw UsageError(fmt::format(
        "refused before starting: the largest model of this selection ({}) needs about {:.2f} GiB, "
        "more than the {:.2f} GiB this run may use ({}); select coarser meshes or free memory",
        largest_name, gib(largest_mib), gib(limit), why));
  }
  MemoryPlan plan{limit, {}};
  if (2.0 * largest_mib > limit) {
    plan.note = fmt::format(
        "memory: scheduled to fit: models run together only while their estimated peaks sum to "
        "at most {:.2f} GiB ({}); the largest ({}) needs about {:.2f} GiB",
        gib(limit), why, largest_name, gib(largest_mib));
  }
  return plan;
}

}  // namespace cs::apps

#pragma once
// The memory a run plans for, decided before it starts.
//
// Each model's peak is estimated from its cost (apps/model_cost.hpp: elements grow as the mesh
// factor squared, S problems x30, Q8 x3) at kMiBPerCostUnit. The run may use what the machine
// has: MemAvailable (platform/available_memory.hpp) less a kMemoryMargin share (for the
// process's own memory, the page cache the kernel keeps and the estimate's error), or
// --max-memory when smaller. The runner (suites/runner.hpp) starts a model only while the
// estimated total of the running ones stays within that budget. Then:
//   - a largest model above the budget: the run is refused before it starts (UsageError, exit 2);
//   - a budget below twice the largest model (the two largest cannot run together): the plan's
//     note says so;
//   - no budget known (no MemAvailable, no --max-memory): 1.5 times the largest model, so that
//     the two largest never run together.

#include <string>

namespace cs::apps {

/// MiB of peak resident memory per unit of group_cost. Measured peaks per unit: S(1/7) VF Q4
/// (cost 1920) 3.8 GB -> 2.0; S(1/7) F Q8 (cost 1440) 3,914 MiB (`case`, whole process) -> 2.72;
/// H_p VF Q8 (cost 192) 0.28 GB -> 1.5 (docs/refinement.md, README). The largest, rounded up.
inline constexpr double kMiBPerCostUnit = 2.75;

/// The share of MemAvailable kept free.
inline constexpr double kMemoryMargin = 0.10;

/// What the run may use.
struct MemoryLimits {
  double available_mib = 0.0;  ///< MemAvailable; <= 0: unknown (no limit from the machine)
  double max_mib = 0.0;        ///< --max-memory; <= 0: none
};

/// The plan: the runner's budget (MiB) and, when it keeps the largest models apart, a line that
/// says so.
struct MemoryPlan {
  double budget_mib = 0.0;
  std::string note;
};

/// Plans the run (see the file comment). `largest_mib` is the largest model's estimate and
/// `largest_name` names it (e.g. "S_1_7/VF/Q8"). Throws UsageError when it cannot fit.
MemoryPlan plan_memory(double largest_mib, const std::string& largest_name,
                       const MemoryLimits& limits);

}  // namespace cs::apps

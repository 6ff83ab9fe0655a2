#pragma once
// The cores this process may run on: the CPUs of its affinity mask (what taskset, a container or
// a batch scheduler's allocation leaves it), not the machine's total.

namespace cs::platform {

/// The number of CPUs in this process's affinity mask; std::thread::hardware_concurrency() when
/// the mask cannot be read; at least 1.
int available_cores();

}  // namespace cs::platform

#pragma once
// The memory the machine can give a new run: MemAvailable of /proc/meminfo (the kernel's
// estimate of what can be allocated without swapping, page cache it can drop included).

#include <string_view>

namespace cs::platform {

/// MemAvailable in MiB from the text of /proc/meminfo; 0 when the line is missing or malformed.
double parse_mem_available_mb(std::string_view meminfo);

/// MemAvailable of this machine in MiB; 0 when /proc/meminfo cannot be read (then no limit is
/// known).
double available_memory_mb();

}  // namespace cs::platform

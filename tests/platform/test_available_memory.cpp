// Requirement (issue 25, item 3): the memory a run plans for starts from the kernel's
// MemAvailable; a missing or malformed line means "unknown", never a made-up number.

#include <gtest/gtest.h>

#include "platform/available_memory.hpp"

namespace cs::platform {
namespace {

TEST(AvailableMemory, ReadsMemAvailableInMiB) {
  const char* meminfo =
      "MemTotal:       16384000 kB\nMemFree:         1024000 kB\nMemAvailable:    2097152 kB\n";
  EXPECT_EQ(parse_mem_available_mb(meminfo), 2048.0);  // 2097152 kB / 1024, exact in binary
}

TEST(AvailableMemory, MissingOrMalformedIsUnknown) {
  EXPECT_EQ(parse_mem_available_mb(""), 0.0);
  EXPECT_EQ(parse_mem_available_mb("MemTotal: 100 kB\n"), 0.0);
  EXPECT_EQ(parse_mem_available_mb("MemAvailable: lots\n"), 0.0);
  EXPECT_EQ(parse_mem_available_mb("MemAvailable: 100"), 0.0);
  EXPECT_EQ(parse_mem_available_mb("XMemAvailable: 100 kB\n"), 0.0);
}

TEST(AvailableMemory, ThisMachineHasSome) {
  EXPECT_GT(available_memory_mb(), 0.0);  // every Linux since 3.14 has the line
}

}  // namespace
}  // namespace cs::platform

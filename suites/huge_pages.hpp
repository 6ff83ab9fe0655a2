#pragma once
// Transparent huge pages for the solver's large arrays. A fine-mesh model allocates gigabytes
// (CHOLMOD's factor, the condensed blocks) in blocks glibc takes from mmap and returns at free,
// so every case touches them again page by page: S(1/7) F Q8's 30 cases took 2.3 million page
// faults and 8.3 s of system time. Where the kernel gives huge pages on request only
// ("madvise"), glibc's tunable glibc.malloc.hugetlb=1 makes malloc ask for them: 34 thousand
// faults, 5.0 s of system time, and the set 31 s instead of 37 s, with the same values bit for
// bit (docs/benchmarks.md, "Huge pages"). Tunables are read when a program starts, so the
// program sets the variable and executes itself again (suites/start_settings.hpp). A user's own
// glibc.malloc.hugetlb is kept.

#include <optional>
#include <string>
#include <string_view>

namespace cs::suites {

/// Whether the kernel gives transparent huge pages only to memory that asks for them: the
/// selected mode of /sys/kernel/mm/transparent_hugepage/enabled (`enabled_text`, e.g.
/// "always [madvise] never") is madvise. With "always" every process has them already; with
/// "never", or an unreadable text, nobody does.
bool huge_pages_on_request(std::string_view enabled_text);

/// The value of GLIBC_TUNABLES (`current`, null when unset) with glibc.malloc.hugetlb=1 added
/// (tunables are separated by ':'), or nothing when `current` already sets glibc.malloc.hugetlb
/// (the user's choice stands).
std::optional<std::string> tunables_with_huge_pages(const char* current);

/// The value GLIBC_TUNABLES should take for this process to get huge pages, read from the kernel
/// and the environment; nothing when it needs no change.
std::optional<std::string> huge_page_tunables();

}  // namespace cs::suites

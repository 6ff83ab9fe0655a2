#include "suites/start_settings.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "suites/blas_kernels.hpp"
#include "suites/huge_pages.hpp"

namespace cs::suites {

void start_with_the_machines_settings(char** argv, const StartSettings& settings) {
  constexpr const char* kAgain = "CONTACT_SUITE_RESTARTED";  // set: this is the second start
  if (std::getenv(kAgain) != nullptr) {
    unsetenv(kAgain);  // not handed on: a child contact-suite decides for itself
    return;
  }
  std::vector<std::pair<const char*, std::string>> changes;
  if (auto kernels = blas_kernels_to_set())
    changes.emplace_back("OPENBLAS_CORETYPE", std::move(*kernels));
  if (settings.huge_pages) {
    if (auto tunables = huge_page_tunables())
      changes.emplace_back("GLIBC_TUNABLES", std::move(*tunables));
  }
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  // Started through the dynamic loader (ld-linux-x86-64.so.2 contact-suite ...), /proc/self/exe
  // is the loader, which would take argv[0] for the program: keep the environment as it is.
  if (changes.empty() || ec || exe.filename().string().starts_with("ld-"))
    return;
  std::vector<std::pair<const char*, std::optional<std::string>>> before;
  for (const auto& [name, value] : changes) {
    const char* old = std::getenv(name);
    before.emplace_back(name, old != nullptr ? std::optional<std::string>(old) : std::nullopt);
  }
  bool set = setenv(kAgain, "1", 1) == 0;
  for (const auto& [name, value] : changes)
    set = set && setenv(name, value.c_str(), 1) == 0;
  if (set)
    execv(exe.c_str(), argv);
  // Not executed again: go on with the environment the program was given.
  for (const auto& [name, old] : before)
    old ? setenv(name, old->c_str(), 1) : unsetenv(name);
  unsetenv(kAgain);
}

}  // namespace cs::suites

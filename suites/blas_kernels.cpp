#include "suites/blas_kernels.hpp"

#include <dlfcn.h>
#include <strings.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace cs::suites {
namespace {

/// The flags of the first processor in /proc/cpuinfo (empty where it cannot be read).
std::set<std::string> cpu_flags() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("flags", 0) != 0)
      continue;
    std::istringstream words(line.substr(line.find(':') + 1));
    return {std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
  }
  return {};
}

/// OpenBLAS's name of the kernels it loaded, or "" for another BLAS.
std::string blas_core_name() {
  using NameFn = char* (*)();
  const auto fn = reinterpret_cast<NameFn>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  const char* name = fn != nullptr ? fn() : nullptr;
  return name != nullptr ? name : "";
}

}  // namespace

std::string_view blas_kernels_for(const std::set<std::string>& flags) {
  const auto has = [&](std::initializer_list<const char*> names) {
    return std::ranges::all_of(names, [&](const char* n) { return flags.contains(n); });
  };
  if (has({"avx512f", "avx512bw", "avx512dq", "avx512vl", "avx512cd"}))
    return has({"avx512_bf16"}) ? "Cooperlake" : "SkylakeX";
  if (has({"avx2", "fma"}))
    return "Haswell";
  return "";
}

void use_the_cpus_blas_kernels(char** argv) {
  constexpr const char* kAgain = "CONTACT_SUITE_BLAS_REEXEC";  // set: this is the second start
  if (std::getenv(kAgain) != nullptr) {
    unsetenv(kAgain);  // not handed on: a child contact-suite decides for itself
    return;
  }
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr ||
      strcasecmp(blas_core_name().c_str(), "Prescott") != 0)
    return;
  const std::string_view kernels = blas_kernels_for(cpu_flags());
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  // Started through the dynamic loader (ld-linux-x86-64.so.2 contact-suite ...), /proc/self/exe
  // is the loader, which would take argv[0] for the program: keep the library's kernels.
  if (kernels.empty() || ec || exe.filename().string().starts_with("ld-"))
    return;
  if (setenv("OPENBLAS_CORETYPE", std::string(kernels).c_str(), 1) != 0 ||
      setenv(kAgain, "1", 1) != 0)
    return;
  execv(exe.c_str(), argv);
  unsetenv("OPENBLAS_CORETYPE");  // the execution failed: go on with the library's kernels
  unsetenv(kAgain);
}

}  // namespace cs::suites

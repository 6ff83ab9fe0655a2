#include "suites/blas_kernels.hpp"

#include <dlfcn.h>
#include <strings.h>

#include <algorithm>
#include <cstdlib>
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

std::optional<std::string> blas_kernels_to_set() {
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr ||
      strcasecmp(blas_core_name().c_str(), "Prescott") != 0)
    return std::nullopt;
  const std::string_view kernels = blas_kernels_for(cpu_flags());
  if (kernels.empty())
    return std::nullopt;
  return std::string(kernels);
}

}  // namespace cs::suites

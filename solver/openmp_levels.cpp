#include "solver/openmp_levels.hpp"

#include <dlfcn.h>

namespace cs::solver {

std::optional<int> openmp_active_levels() {
  using GetFn = int (*)();
  const auto get = reinterpret_cast<GetFn>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  return get != nullptr ? std::optional<int>(get()) : std::nullopt;
}

bool set_openmp_active_levels(int levels) {
  using SetFn = void (*)(int);
  const auto set = reinterpret_cast<SetFn>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
  if (set == nullptr)
    return false;
  set(levels);
  return true;
}

}  // namespace cs::solver

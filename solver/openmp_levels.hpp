#pragma once
// The OpenMP runtime's max-active-levels, read and set through the loaded runtime: the solver's
// libraries (CHOLMOD) load libgomp, the solver does not link it. libgomp keeps the setting per
// thread, so a thread that should run the libraries' OpenMP regions as another does sets it
// itself.

#include <optional>

namespace cs::solver {

/// The calling thread's max-active-levels, or nothing when no OpenMP runtime is loaded.
std::optional<int> openmp_active_levels();

/// Sets the calling thread's max-active-levels (0: every parallel region runs on the thread
/// that meets it); false when no OpenMP runtime is loaded.
bool set_openmp_active_levels(int levels);

}  // namespace cs::solver

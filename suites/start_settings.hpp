#pragma once
// What a process of the tool sets in its own environment before it works, and the one restart
// that makes the libraries read it: OpenBLAS's kernels for this CPU (suites/blas_kernels.hpp) and,
// for the commands that solve models, glibc's huge pages (suites/huge_pages.hpp). Both are read
// only when a program starts, so the program sets the variables and executes itself again
// (/proc/self/exe, the same argv) before anything else runs. CONTACT_SUITE_RESTARTED marks the
// second start, so that it never repeats (set by hand, it keeps the environment as it is). The
// variables stay set for the programs the tool starts (ccx, a Python adapter's NumPy).

namespace cs::suites {

struct StartSettings {
  bool huge_pages = false;  ///< ask glibc for transparent huge pages (large models)
};

/// Sets what blas_kernels_to_set() and, with `settings.huge_pages`, huge_page_tunables() ask for
/// and executes this program with `argv` again. Returns (doing nothing) when nothing needs
/// setting, on the second start, when the program was started through the dynamic loader, or
/// when the execution fails (the environment is then restored).
void start_with_the_machines_settings(char** argv, const StartSettings& settings);

}  // namespace cs::suites

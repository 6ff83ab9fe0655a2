#pragma once
// OpenBLAS's kernels for a CPU newer than the library. Debian 12's OpenBLAS (0.3.21, built with
// DYNAMIC_ARCH) picks its kernels at load time by the CPU's family and model; a model it does not
// know (Emerald Rapids, family 6 model 207) falls back to Prescott's SSE3 kernels, which take
// the main job 1.37 times the CPU time of the AVX-512 ones (196 s against 144 s; wall 103 s
// against 76 s, one pair on a quiet machine). The library reads OPENBLAS_CORETYPE only when it
// is loaded, so the program sets it and executes itself again before anything else runs
// (suites/start_settings.hpp). A user's own OPENBLAS_CORETYPE is kept; a library that is not
// OpenBLAS is left alone. The variable stays set for the programs the tool starts (ccx, a Python
// adapter's NumPy), which load the same library.

#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace cs::suites {

/// The OpenBLAS kernel set for a CPU with the flags `flags` (/proc/cpuinfo's names):
/// "Cooperlake" with AVX-512 (f, bw, dq, vl, cd) and avx512_bf16, "SkylakeX" with AVX-512
/// alone, "Haswell" with avx2 and fma, else "" (none better than the library's).
std::string_view blas_kernels_for(const std::set<std::string>& flags);

/// The value OPENBLAS_CORETYPE should take: blas_kernels_for() this CPU when OpenBLAS fell back
/// to Prescott and OPENBLAS_CORETYPE is not set; nothing otherwise.
std::optional<std::string> blas_kernels_to_set();

}  // namespace cs::suites

#pragma once
// OpenBLAS's kernels for a CPU newer than the library. Debian 12's OpenBLAS (0.3.21, built with
// DYNAMIC_ARCH) picks its kernels at load time by the CPU's family and model; a model it does not
// know (Emerald Rapids, family 6 model 207) falls back to Prescott's SSE3 kernels, which take
// the main job 1.37 times the CPU time of the AVX-512 ones (196 s against 144 s; wall 103 s
// against 76 s, one pair on a quiet machine). The library reads OPENBLAS_CORETYPE only when it
// is loaded, so the program sets it and executes itself again before anything else runs.
// A user's own OPENBLAS_CORETYPE is kept; a library that is not OpenBLAS is left alone. The
// variable stays set for the programs the tool starts (ccx, a Python adapter's NumPy), which load
// the same library; CONTACT_SUITE_BLAS_REEXEC marks the second start, so that it never repeats
// (set by hand, it keeps the library's own choice).

#include <set>
#include <string>
#include <string_view>

namespace cs::suites {

/// The OpenBLAS kernel set for a CPU with the flags `flags` (/proc/cpuinfo's names):
/// "Cooperlake" with AVX-512 (f, bw, dq, vl, cd) and avx512_bf16, "SkylakeX" with AVX-512
/// alone, "Haswell" with avx2 and fma, else "" (none better than the library's).
std::string_view blas_kernels_for(const std::set<std::string>& flags);

/// When OpenBLAS fell back to Prescott on a CPU that blas_kernels_for() gives a better set,
/// and OPENBLAS_CORETYPE is not set: sets it and executes this program (/proc/self/exe) with
/// `argv` again. Returns (doing nothing) otherwise: on the second start, when the program was
/// started through the dynamic loader, or when the execution fails.
void use_the_cpus_blas_kernels(char** argv);

}  // namespace cs::suites

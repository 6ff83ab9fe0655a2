// Requirement: the OpenBLAS kernels for a CPU the library does not know follow its features:
// AVX-512 (with bf16: Cooperlake's set, else SkylakeX's), AVX2 with FMA (Haswell's), nothing
// better for an older CPU. Fails if a flag set is mapped to kernels the CPU cannot run.

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "suites/blas_kernels.hpp"

namespace cs::suites {
namespace {

TEST(BlasKernels, FollowTheCpusFeatures) {
  const std::set<std::string> avx2{"sse4_2", "avx", "avx2", "fma"};
  std::set<std::string> avx512 = avx2;
  avx512.insert({"avx512f", "avx512bw", "avx512dq", "avx512vl", "avx512cd"});
  std::set<std::string> bf16 = avx512;
  bf16.insert("avx512_bf16");
  EXPECT_EQ(blas_kernels_for(bf16), "Cooperlake");
  EXPECT_EQ(blas_kernels_for(avx512), "SkylakeX");
  EXPECT_EQ(blas_kernels_for(avx2), "Haswell");
  std::set<std::string> partial = avx2;
  partial.insert("avx512f");  // AVX-512 without the rest (Knights Landing): not SkylakeX's
  EXPECT_EQ(blas_kernels_for(partial), "Haswell");
  EXPECT_EQ(blas_kernels_for({"sse4_2", "avx"}), "");  // no FMA: the library's own choice
  EXPECT_EQ(blas_kernels_for({}), "");
}

}  // namespace
}  // namespace cs::suites

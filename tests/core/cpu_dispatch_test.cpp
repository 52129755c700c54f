// The dispatch of the hot kernels (core/base/cpu_dispatch.h): on a CPU with AVX2 and FMA the portable build runs their
// x86-64-v3 copy. The reported target is observed (a dispatched function fused a multiply-add or not) and checked
// here against the CPU's own feature flags. That the baseline copy runs, and agrees, on a CPU without them is
// tests/python/test_portable_build.py (qemu's Nehalem).
#include "base/cpu_dispatch.h"

#include <gtest/gtest.h>

#include <string>

namespace somicage {
namespace {

TEST(CpuDispatch, RunsTheAvx2FmaCopyExactlyWhereTheCpuHasIt) {
#ifdef SOMICAGE_SANITIZE
  // The sanitizer build compiles -O1, where GCC forms no fused multiply-add, so the observation cannot tell the
  // copies apart there; the Release build runs this test.
  GTEST_SKIP() << "the dispatch is observed through a fused multiply-add, which -O1 (sanitizer build) never forms";
#endif
  const std::string target = dispatchedKernelTarget();
#if SOMICAGE_DISPATCH_CLONES
  const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  EXPECT_EQ(target, v3 ? "x86-64-v3" : "baseline");
#elif defined(__AVX2__) && defined(__FMA__)
  EXPECT_EQ(target, "native");  // SOMICAGE_NATIVE on this CPU
#else
  EXPECT_EQ(target, "baseline");  // clang, other architectures: one copy
#endif
}

}  // namespace
}  // namespace somicage

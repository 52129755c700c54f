// The run-time choice of the per-ISA kernels (core/base/cpu_dispatch.h): the portable GCC build on x86-64 has
// baseline, x86-64-v3 and x86-64-v4 copies of the row kernels and runs the highest this CPU supports, checked here
// against the CPU's own feature flags (the features GCC's -march=x86-64-v3 and v4 add, named one by one). That the
// baseline copy runs, and agrees, on a CPU without them is tests/python/test_portable_build.py (qemu's Nehalem).
#include "base/cpu_dispatch.h"

#include <gtest/gtest.h>

#include <string>

namespace somicage {
namespace {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
bool cpuHasX86_64V3() {
  for (const bool has : {__builtin_cpu_supports("avx"), __builtin_cpu_supports("avx2"), __builtin_cpu_supports("bmi"),
                         __builtin_cpu_supports("bmi2"), __builtin_cpu_supports("fma"), __builtin_cpu_supports("f16c"),
                         __builtin_cpu_supports("movbe"), __builtin_cpu_supports("lzcnt"),
                         __builtin_cpu_supports("xsave")})
    if (!has) return false;
  return true;
}

bool cpuHasX86_64V4() {
  return cpuHasX86_64V3() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl");
}
#endif

TEST(CpuDispatch, RunsTheHighestCopyTheCpuHas) {
  const std::string target = dispatchedKernelTarget();
  EXPECT_TRUE(kernelIsaAvailable(KernelIsa::baseline));
#if defined(__AVX2__) && defined(__FMA__)
  EXPECT_EQ(target, "native");  // SOMICAGE_NATIVE on this CPU: one copy, for it
#elif defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  // The copies of this build: x86-64-v3 and v4 wherever GCC builds for x86-64 (core/CMakeLists.txt).
  const bool v3 = cpuHasX86_64V3(), v4 = cpuHasX86_64V4();
  EXPECT_EQ(kernelIsaAvailable(KernelIsa::x86_64_v3), v3);
  EXPECT_EQ(kernelIsaAvailable(KernelIsa::x86_64_v4), v4);
  EXPECT_EQ(target, v4 ? "x86-64-v4" : v3 ? "x86-64-v3" : "baseline");
  EXPECT_EQ(target, kernelIsaName(selectedKernelIsa()));
#else
  EXPECT_EQ(target, "baseline");  // clang, other architectures: one copy
#endif
}

}  // namespace
}  // namespace somicage

#include "base/cpu_dispatch.h"

namespace somicage {

#if SOMICAGE_DISPATCH_CLONES
namespace {

// a * b + c with a b = 1 - 2^-60 and c = -1 (CMake compiles this file with -ffp-contract=fast): a fused multiply-add
// keeps the -2^-60, a rounded product (1) loses it. Only the x86-64-v3 copy has FMA instructions.
SOMICAGE_DISPATCH double multiplyAdd(double a, double b, double c) { return a * b + c; }

}  // namespace
#endif

const char* dispatchedKernelTarget() {
#if SOMICAGE_DISPATCH_CLONES
  volatile double a = 1 + 0x1p-30, b = 1 - 0x1p-30, c = -1;  // volatile: nothing to fold at compile time
  return multiplyAdd(a, b, c) != 0 ? "x86-64-v3" : "baseline";
#elif defined(__AVX2__) && defined(__FMA__)
  return "native";
#else
  return "baseline";
#endif
}

}  // namespace somicage

#include "base/cpu_dispatch.h"

namespace somicage {

// SOMICAGE_HAS_X86_64_V3 / _V4: the build compiled the per-ISA kernels for that level (core/CMakeLists.txt).
bool kernelIsaAvailable(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::baseline:
      return true;
    case KernelIsa::x86_64_v3:
#ifdef SOMICAGE_HAS_X86_64_V3
      return __builtin_cpu_supports("x86-64-v3");  // the feature set of GCC's -march=x86-64-v3
#else
      return false;
#endif
    case KernelIsa::x86_64_v4:
#ifdef SOMICAGE_HAS_X86_64_V4
      return __builtin_cpu_supports("x86-64-v4");
#else
      return false;
#endif
  }
  return false;
}

KernelIsa selectedKernelIsa() {
  static const KernelIsa isa = kernelIsaAvailable(KernelIsa::x86_64_v4)   ? KernelIsa::x86_64_v4
                               : kernelIsaAvailable(KernelIsa::x86_64_v3) ? KernelIsa::x86_64_v3
                                                                          : KernelIsa::baseline;
  return isa;
}

const char* kernelIsaName(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::x86_64_v3:
      return "x86-64-v3";
    case KernelIsa::x86_64_v4:
      return "x86-64-v4";
    case KernelIsa::baseline:
      break;
  }
  return "baseline";
}

const char* dispatchedKernelTarget() {
#if defined(__AVX2__) && defined(__FMA__)
  return "native";
#else
  return kernelIsaName(selectedKernelIsa());
#endif
}

}  // namespace somicage

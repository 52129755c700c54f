#include "coordinates/somigliana_row_kernels.h"

#include "base/simd_pack.h"

namespace somicage {

#if SOMICAGE_SIMD_PACKS
// Each copy's table, defined in somigliana_row_kernels_isa.cpp compiled for that ISA (core/CMakeLists.txt).
namespace isa_baseline {
extern const SomiglianaRowKernels kSomiglianaRowKernels;
}
#ifdef SOMICAGE_HAS_X86_64_V3
namespace isa_x86_64_v3 {
extern const SomiglianaRowKernels kSomiglianaRowKernels;
}
#endif
#ifdef SOMICAGE_HAS_X86_64_V4
namespace isa_x86_64_v4 {
extern const SomiglianaRowKernels kSomiglianaRowKernels;
}
#endif
#endif

const SomiglianaRowKernels* somiglianaRowKernelsFor(KernelIsa isa) {
  if (!kernelIsaAvailable(isa)) return nullptr;
  switch (isa) {
#if SOMICAGE_SIMD_PACKS
    case KernelIsa::baseline:
      return &isa_baseline::kSomiglianaRowKernels;
#ifdef SOMICAGE_HAS_X86_64_V3
    case KernelIsa::x86_64_v3:
      return &isa_x86_64_v3::kSomiglianaRowKernels;
#endif
#ifdef SOMICAGE_HAS_X86_64_V4
    case KernelIsa::x86_64_v4:
      return &isa_x86_64_v4::kSomiglianaRowKernels;
#endif
#endif
    default:
      return nullptr;
  }
}

const SomiglianaRowKernels& somiglianaRowKernels() {
  static const SomiglianaRowKernels* const kernels = somiglianaRowKernelsFor(selectedKernelIsa());
  return *kernels;
}

}  // namespace somicage

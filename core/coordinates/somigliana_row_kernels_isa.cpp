// One instruction set's copy of the Somigliana row kernels (somigliana_row_kernels.h). Not compiled as itself:
// core/CMakeLists.txt compiles it once per ISA, with -DSOMICAGE_ISA=isa_NAME (the namespace of every inline function
// it instantiates, base/isa_namespace.h), that ISA's -march and, for x86-64-v4, -DSOMICAGE_SIMD_LANES=8. Nothing
// here may call an inline function from outside those namespaces (Eigen, the standard library's templates): the
// linker could keep this copy of it for the baseline code. The ctest core.isa_symbols (tools/check_isa_symbols.py) checks.
#include "base/simd_math.h"
#include "coordinates/somigliana_gradient_row.h"
#include "coordinates/somigliana_row_kernels.h"
#include "coordinates/somigliana_row_portable.h"

#ifndef SOMICAGE_ISA
#error "compiled only per ISA, with -DSOMICAGE_ISA=isa_NAME (core/CMakeLists.txt)"
#endif

#if SOMICAGE_SIMD_PACKS
namespace somicage {
SOMICAGE_ISA_BEGIN
namespace {

void loadPoints(const double* x, simd::Pack p[3]) {
  for (int a = 0; a < 3; ++a)
    for (int l = 0; l < simd::kLanes; ++l) p[a].v[l] = x[a * simd::kLanes + l];
}

// The whole hot work of a call, the closed form and the accumulation inlined (flatten). `rows` is a PackBuffer's,
// so aligned for the packs.
__attribute__((flatten)) void rows(const PortableFace* faces, int numFaces, int numVertices, const double* x,
                                   double* rows, double* winding) {
  simd::Pack p[3];
  loadPoints(x, p);
  const simd::Pack w =
      integrateSomiglianaRowPortable(faces, numFaces, numVertices, p, reinterpret_cast<simd::Pack*>(rows), 1);
  for (int l = 0; l < simd::kLanes; ++l) winding[l] = w.v[l];
}

__attribute__((flatten)) void gradientRows(const PortableFace* faces, const PortableGradientFrame* tables,
                                           int numFaces, int numVertices, const double* x, double* rows) {
  simd::Pack p[3];
  loadPoints(x, p);
  integrateSomiglianaGradientRowPortable(faces, tables, numFaces, numVertices, p,
                                         reinterpret_cast<simd::Pack*>(rows));
}

}  // namespace

extern const SomiglianaRowKernels kSomiglianaRowKernels;
const SomiglianaRowKernels kSomiglianaRowKernels = {simd::kLanes, rows, gradientRows};

SOMICAGE_ISA_END
}  // namespace somicage
#endif

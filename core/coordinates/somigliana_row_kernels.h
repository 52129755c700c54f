// The Somigliana row kernels of the CPU precompute, one copy per instruction set (docs/performance.md, "One binary
// for every CPU"): the rows of a group of points (one per SIMD lane) against every face, the coordinates'
// (somigliana_row_portable.h) and the gradients' (somigliana_gradient_row.h). somigliana_row_kernels_isa.cpp is
// compiled once per ISA, each copy in its own namespace (base/isa_namespace.h), with its own lane count;
// somiglianaRowKernels() hands out the copy this CPU runs, chosen once.
#pragma once

#include <cstddef>
#include <memory>
#include <new>

#include "base/cpu_dispatch.h"
#include "coordinates/somigliana_row_portable.h"
#include "geometry/triangle_gradients_kernel.h"

namespace somicage {

// One copy's entries. Points come `lanes` at a time: x[a * lanes + l] is coordinate a of lane l's point. Outputs are
// lane-interleaved, entry k of lane l at out[k * lanes + l], in a PackBuffer (aligned for the copy's vectors).
struct SomiglianaRowKernels {
  int lanes;
  // The rows (numVertices * 10 + numFaces * 4 + 18 entries) and the winding numbers (`lanes` of them).
  void (*rows)(const PortableFace* faces, int numFaces, int numVertices, const double* x, double* rows,
               double* winding);
  // The three gradient rows, interleaved as integrateSomiglianaGradientRowPortable's (entry k of row a at 3k + a);
  // tables[j] = makeGradientFrame(faces[j].frame) (triangle_gradients_kernel.h), made once per cage.
  void (*gradientRows)(const PortableFace* faces, const PortableGradientFrame* tables, int numFaces, int numVertices,
                       const double* x, double* rows);
  // The lanes' rows of such a buffer as `lanes` consecutive rows of a float matrix, `columns` floats each from `out`:
  // entry c < packedColumns of lane l from in[c * entryStride + l], the rest from tail[l * (columns - packedColumns) +
  // c - packedColumns]. Every whole cache line goes out with a non-temporal store: a matrix written once and much
  // larger than the caches (the gradients') would otherwise be read into the cache before each line is written.
  void (*streamFloatRows)(const double* in, long entryStride, int packedColumns, const double* tail, int columns,
                          float* out);
  // sums[l] = the sum of lane l's entries k < count of such a buffer (in[k * entryStride + l]), added in order.
  void (*sumEntries)(const double* in, long entryStride, int count, double* sums);
};

// The copy for `isa`, or nullptr where this build has none or the CPU does not run it (kernelIsaAvailable). Only
// builds with SIMD packs (simd_pack.h) have any; the others run the scalar kernels.
const SomiglianaRowKernels* somiglianaRowKernelsFor(KernelIsa isa);

// The copy for selectedKernelIsa().
const SomiglianaRowKernels& somiglianaRowKernels();

// Doubles aligned for every copy's packs (64 bytes: eight lanes of AVX-512).
struct PackBufferDelete {
  void operator()(double* p) const { ::operator delete(p, std::align_val_t{64}); }
};
using PackBuffer = std::unique_ptr<double[], PackBufferDelete>;
inline PackBuffer makePackBuffer(std::size_t count) {
  return PackBuffer(static_cast<double*>(::operator new(count * sizeof(double), std::align_val_t{64})));
}

}  // namespace somicage

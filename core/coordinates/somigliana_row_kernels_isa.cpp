// One instruction set's copy of the Somigliana row kernels (somigliana_row_kernels.h). Not compiled as itself:
// core/CMakeLists.txt compiles it once per ISA, with -DSOMICAGE_ISA=isa_NAME (the namespace of every inline function
// it instantiates, base/isa_namespace.h), that ISA's -march and, for x86-64-v4, -DSOMICAGE_SIMD_LANES=8. Nothing
// here may call an inline function from outside those namespaces (Eigen, the standard library's templates): the
// linker could keep this copy of it for the baseline code. The ctest core.isa_symbols (tools/check_isa_symbols.py) checks.
#include <immintrin.h>
#include <stdint.h>

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

constexpr int kLineFloats = 16;  // a 64-byte cache line

typedef float Floats4 __attribute__((vector_size(16)));
typedef double Doubles4 __attribute__((vector_size(32)));

// Writes a cache line (`to` 64-byte aligned) from `line` without reading it first.
void streamLine(const float* line, float* to) {
#if defined(__AVX512F__)
  _mm512_stream_ps(to, _mm512_load_ps(line));
#elif defined(__AVX__)
  _mm256_stream_ps(to, _mm256_load_ps(line)), _mm256_stream_ps(to + 8, _mm256_load_ps(line + 8));
#else
  for (int q = 0; q < kLineFloats; q += 4) _mm_stream_ps(to + q, _mm_load_ps(line + q));
#endif
}

// streamLine for the floats j < 16 of in[j * entryStride]. AVX-512 and AVX2 gather the strided doubles (in the
// masked forms: GCC 12 warns that the unmasked ones read an undefined register); the baseline copy loads them one by
// one.
void streamGatheredLine(const double* in, long entryStride, float* to) {
  const long s = entryStride;
#if defined(__AVX512F__)
  typedef float Floats8 __attribute__((vector_size(32)));
  typedef double Doubles8 __attribute__((vector_size(64)));
  const __m512i index = _mm512_set_epi64(7 * s, 6 * s, 5 * s, 4 * s, 3 * s, 2 * s, s, 0);
  const auto gather = [&](const double* from) {
    const __m512d d = _mm512_mask_i64gather_pd(_mm512_setzero_pd(), 0xff, index, from, 8);
    return (__m256)__builtin_convertvector((Doubles8)d, Floats8);
  };
  _mm512_stream_ps(to, _mm512_insertf32x8(_mm512_castps256_ps512(gather(in)), gather(in + 8 * s), 1));
#elif defined(__AVX2__)
  const __m256i index = _mm256_set_epi64x(3 * s, 2 * s, s, 0);
  const __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const auto gather = [&](const double* from) {
    const __m256d d = _mm256_mask_i64gather_pd(_mm256_setzero_pd(), from, index, all, 8);
    return (__m128)__builtin_convertvector((Doubles4)d, Floats4);
  };
  for (int half = 0; half < 2; ++half)
    _mm256_stream_ps(to + 8 * half, _mm256_set_m128(gather(in + (8 * half + 4) * s), gather(in + 8 * half * s)));
#else
  for (int quarter = 0; quarter < 4; ++quarter) {
    const double* from = in + 4 * quarter * s;
    const Doubles4 d = {from[0], from[s], from[2 * s], from[3 * s]};
    _mm_stream_ps(to + 4 * quarter, (__m128)__builtin_convertvector(d, Floats4));
  }
#endif
}

void streamFloatRows(const double* in, long entryStride, int packedColumns, const double* tail, int columns,
                     float* out) {
  constexpr int lanes = simd::kLanes;
  const int tailColumns = columns - packedColumns;
  const long total = static_cast<long>(lanes) * columns;
  const auto value = [&](long e) {  // out[e], from the lane and column it belongs to
    const int lane = static_cast<int>(e / columns), column = static_cast<int>(e % columns);
    return static_cast<float>(column < packedColumns ? in[column * entryStride + lane]
                                                     : tail[lane * tailColumns + column - packedColumns]);
  };
  // out's cache lines start at out + firstLine + 16 m (out is float-aligned); the first such start at or after e:
  const long firstLine = static_cast<long>((64 - (reinterpret_cast<uintptr_t>(out) & 63)) & 63) / sizeof(float);
  const auto lineStartFrom = [&](long e) { return e + ((firstLine - e) % kLineFloats + kLineFloats) % kLineFloats; };

  // The whole lines within a lane's packed columns, gathered for each line number lane after lane, so that the packs
  // they read (32 columns of every lane) stay in the L1 cache.
  long fastBegin[lanes], fastEnd[lanes], fastLines = 0;
  for (int l = 0; l < lanes; ++l) {
    const long rowStart = static_cast<long>(l) * columns, packedEnd = rowStart + packedColumns;
    const long begin = lineStartFrom(rowStart), lines = packedEnd > begin ? (packedEnd - begin) / kLineFloats : 0;
    fastBegin[l] = lines > 0 ? begin : rowStart;  // an empty range stays in its row: the rest below is in order
    fastEnd[l] = fastBegin[l] + lines * kLineFloats;
    fastLines = lines > fastLines ? lines : fastLines;
  }
  for (long m = 0; m < fastLines; ++m)
    for (int l = 0; l < lanes; ++l) {
      const long e = fastBegin[l] + m * kLineFloats, column = e - static_cast<long>(l) * columns;
      if (e < fastEnd[l]) streamGatheredLine(in + column * entryStride + l, entryStride, out + e);
    }

  // The rest (the tails, the lines across two rows): whole lines assembled a float at a time, and the floats before
  // the span's first whole line and after its last (lines shared with the rows around the span) stored as usual.
  const auto writeRest = [&](long begin, long end) {
    long e = begin;
    for (const long lineStart = lineStartFrom(begin); e < end && e < lineStart; ++e) out[e] = value(e);
    for (; e + kLineFloats <= end; e += kLineFloats) {
      alignas(64) float line[kLineFloats];
      for (int j = 0; j < kLineFloats; ++j) line[j] = value(e + j);
      streamLine(line, out + e);
    }
    for (; e < end; ++e) out[e] = value(e);
  };
  writeRest(0, fastBegin[0]);
  for (int l = 0; l < lanes; ++l) writeRest(fastEnd[l], l + 1 < lanes ? fastBegin[l + 1] : total);
  _mm_sfence();  // the streamed lines are visible to other threads before the caller goes on
}

void sumEntries(const double* in, long entryStride, int count, double* sums) {
  simd::Pack sum = 0.0;
  for (int k = 0; k < count; ++k) sum += *reinterpret_cast<const simd::Pack*>(in + k * entryStride);
  for (int l = 0; l < simd::kLanes; ++l) sums[l] = sum.v[l];
}

}  // namespace

extern const SomiglianaRowKernels kSomiglianaRowKernels;
const SomiglianaRowKernels kSomiglianaRowKernels = {simd::kLanes, rows, gradientRows, streamFloatRows, sumEntries};

SOMICAGE_ISA_END
}  // namespace somicage
#endif

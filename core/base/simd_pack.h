// simd::Pack: kLanes doubles that the closed-form kernels (triangle_integrals_kernel.h) evaluate together, one
// query point per lane, as their Scalar type. Built on the GCC/clang vector extensions rather than intrinsics, so
// that each copy of a dispatched function (cpu_dispatch.h) lowers it to its own instructions: two SSE2 operations
// per pack in the baseline copy, one AVX2 operation in the x86-64-v3 copy. Elsewhere (other architectures, other
// compilers, CUDA) SOMICAGE_SIMD_PACKS is 0 and the callers run the scalar kernel.
//
// Arithmetic is lane by lane with IEEE rounding, exactly as the scalar kernel's; the transcendental functions are
// simd_math.h's. Vectors live only inside structs passed by reference: a 32-byte vector passed by value would have
// a different ABI in the SSE2 and AVX copies (GCC's -Wpsabi).
#pragma once

#include "base/branch_select.h"
#include "base/isa_namespace.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__CUDACC__)
#define SOMICAGE_SIMD_PACKS 1
#else
#define SOMICAGE_SIMD_PACKS 0
#endif

#if SOMICAGE_SIMD_PACKS

namespace somicage {
SOMICAGE_ISA_BEGIN
namespace simd {

// Four lanes (one AVX2 register, two SSE2 ones); the x86-64-v4 copy of the row kernels is compiled with eight
// (-DSOMICAGE_SIMD_LANES=8: one AVX-512 register).
#ifdef SOMICAGE_SIMD_LANES
constexpr int kLanes = SOMICAGE_SIMD_LANES;
#else
constexpr int kLanes = 4;
#endif

typedef double VecD __attribute__((vector_size(8 * kLanes)));
typedef long long VecI __attribute__((vector_size(8 * kLanes)));

// A lane-wise condition: all bits set where true.
struct Mask {
  VecI bits;
  bool any() const {
    long long r = 0;
    for (int l = 0; l < kLanes; ++l) r |= bits[l];
    return r != 0;
  }
  bool all() const {
    long long r = -1;
    for (int l = 0; l < kLanes; ++l) r &= bits[l];
    return r == -1;
  }
};

// Aligned to its size explicitly: GCC caps a vector type's own alignment at 16 bytes without AVX, while the AVX copy
// of a dispatched function moves packs with aligned 32-byte loads.
struct alignas(8 * kLanes) Pack {
  VecD v;

  // NOLINTNEXTLINE: implicit, so constants mix with packs as with doubles; every lane x (x - 0 keeps a -0)
  Pack(double x = 0) : v(x - VecD{}) {}
  static Pack of(const VecD& w) {
    Pack p;
    p.v = w;
    return p;
  }
  static Pack fromBits(const VecI& b) { return of((VecD)b); }  // same size: a reinterpretation of the bits

  Pack& operator+=(const Pack& o) { return v += o.v, *this; }
  Pack& operator-=(const Pack& o) { return v -= o.v, *this; }
  Pack& operator*=(const Pack& o) { return v *= o.v, *this; }
  Pack& operator/=(const Pack& o) { return v /= o.v, *this; }
};
static_assert(sizeof(Pack) == 8 * kLanes && alignof(Pack) == 8 * kLanes, "a pack is its lanes, aligned");

inline Pack operator+(const Pack& a, const Pack& b) { return Pack::of(a.v + b.v); }
inline Pack operator-(const Pack& a, const Pack& b) { return Pack::of(a.v - b.v); }
inline Pack operator*(const Pack& a, const Pack& b) { return Pack::of(a.v * b.v); }
inline Pack operator/(const Pack& a, const Pack& b) { return Pack::of(a.v / b.v); }
inline Pack operator-(const Pack& a) { return Pack::of(-a.v); }

inline Mask operator<(const Pack& a, const Pack& b) { return {a.v < b.v}; }
inline Mask operator<=(const Pack& a, const Pack& b) { return {a.v <= b.v}; }
inline Mask operator>(const Pack& a, const Pack& b) { return {a.v > b.v}; }
inline Mask operator>=(const Pack& a, const Pack& b) { return {a.v >= b.v}; }

// m ? a : b, lane by lane.
inline Pack select(const Mask& m, const Pack& a, const Pack& b) {
  return Pack::fromBits(((VecI)a.v & m.bits) | ((VecI)b.v & ~m.bits));
}

// branch_select.h for packs (and dual numbers of packs, whose select is dual_number.h's): only the branch some
// lane takes runs, both when the lanes disagree.
template <typename Then, typename Else>
inline auto branchSelect(const Mask& m, Then then, Else otherwise) -> decltype(then()) {
  if (m.all()) return then();
  if (!m.any()) return otherwise();
  const auto a = then(), b = otherwise();
  return {select(m, a.first, b.first), select(m, a.second, b.second)};
}

}  // namespace simd
SOMICAGE_ISA_END
}  // namespace somicage

#endif  // SOMICAGE_SIMD_PACKS

// sqrt, log1p and atan2 for simd::Pack (simd_pack.h), what the closed-form kernels call, found by argument-
// dependent lookup as the dual numbers' are. Branch-free arithmetic on all lanes (lanes that a branchSelect
// discards may hold any value; nothing traps), with fdlibm's (Sun, 1993) argument reductions and minimax
// polynomials, which have errors below 1 ulp; the reductions here add at most about 1 ulp more:
//   sqrt: correctly rounded (the hardware instruction), as ::sqrt.
//   log1p(x), x >= 0 finite: within 2 ulp of glibc's (asserted; measured at most 1 ulp: simd_math_test.cpp).
//   atan2(y, x), finite, not both 0: within 2 ulp of glibc's (asserted; measured at most 1 ulp), signed zeros and
//   the quadrants as glibc's; atan2(0, -0) is 0 (glibc: pi), which the kernels never ask (a point on the cage).
// The kernels' results then differ from the libm-based scalar kernel by a few units of rounding of each log and
// angle term, far inside the 1e-13 the precompute promises (simd_precompute_test.cpp).
#pragma once

#include <math.h>

#include "base/isa_namespace.h"
#include "base/simd_pack.h"

#if SOMICAGE_SIMD_PACKS

namespace somicage {
SOMICAGE_ISA_BEGIN
namespace simd {

constexpr long long kSignBit = -0x7fffffffffffffffLL - 1;  // 1 << 63 without a signed shift

inline Pack sqrt(const Pack& x) {
  Pack r;
  for (int l = 0; l < kLanes; ++l) r.v[l] = __builtin_sqrt(x.v[l]);  // one vsqrtpd with -fno-math-errno
  return r;
}

inline Pack abs(const Pack& x) { return Pack::fromBits((VecI)x.v & ~kSignBit); }

// log(u) for u >= 1 finite: u = 2^k m with m in [sqrt(2)/2, sqrt(2)), f = m - 1, s = f / (2 + f),
// log(m) = f - f^2/2 + s (f^2/2 + R(s^2)) with fdlibm's Lg1..Lg7 (e_log.c, error < 1 ulp).
inline Pack logAtLeastOne(const Pack& u) {
  const VecI bits = (VecI)u.v;
  const VecI mantissa = (bits & 0x000fffffffffffffLL) | 0x3ff0000000000000LL;  // m in [1, 2)
  VecI k = ((bits >> 52) & 0x7ff) - 1023;
  Pack m = Pack::fromBits(mantissa);
  const Mask high = m > Pack(1.41421356237309504880);
  m = select(high, m * 0.5, m);
  k -= high.bits;  // the mask is -1 where true
  const Pack dk = Pack::of(__builtin_convertvector(k, VecD));
  const Pack f = m - 1.0, s = f / (f + 2.0), z = s * s, w = z * z;
  const Pack t1 = w * (3.999999999940941908e-01 + w * (2.222219843214978396e-01 + w * 1.531383769920937332e-01));
  const Pack t2 = z * (6.666666666666735130e-01 +
                       w * (2.857142874366239149e-01 + w * (1.818357216161805012e-01 + w * 1.479819860511658591e-01)));
  const Pack R = t1 + t2, hfsq = 0.5 * f * f;
  const double ln2Hi = 6.93147180369123816490e-01, ln2Lo = 1.90821492927058770002e-10;
  return s * (hfsq + R) + dk * ln2Lo - hfsq + f + dk * ln2Hi;
}

// log1p(x) = log(u) + c / u with u = 1 + x rounded and c = x - (u - 1) its rounding error (exact for u < 2, and
// 1 - (u - x) above: musl's s_log1p.c); for x below eps/2, u = 1 and the result is x.
inline Pack log1p(const Pack& x) {
  const Pack u = x + 1.0;
  const Pack c = select(u < Pack(2.0), x - (u - 1.0), 1.0 - (u - x));
  return logAtLeastOne(u) + c / u;
}

// atan(t) for t in [0, 1]: fdlibm's s_atan.c with its reductions to |z| < 7/16 (t < 7/16: z = t;
// t < 11/16: atan(1/2) + atan((2t - 1)/(2 + t)); else pi/4 + atan((t - 1)/(t + 1))) and its 11-term polynomial.
inline Pack atanUnit(const Pack& t) {
  const Mask lower = t < Pack(0.4375), middle = t < Pack(0.6875);
  const Pack z = select(lower, t, select(middle, (2.0 * t - 1.0) / (2.0 + t), (t - 1.0) / (t + 1.0)));
  const Pack hi = select(lower, 0.0, select(middle, 4.63647609000806093515e-01, 7.85398163397448278999e-01));
  const Pack lo = select(lower, 0.0, select(middle, 2.26987774529616870924e-17, 3.06161699786838301793e-17));
  const Pack zz = z * z, w = zz * zz;
  const Pack s1 = zz * (3.33333333333329318027e-01 +
                        w * (1.42857142725034663711e-01 +
                             w * (9.09088713343650656196e-02 +
                                  w * (6.66107313738753120669e-02 +
                                       w * (4.97687799461593236017e-02 + w * 1.62858201153657823623e-02)))));
  const Pack s2 = w * (-1.99999999998764832476e-01 +
                       w * (-1.11111104054623557880e-01 +
                            w * (-7.69187620504482999495e-02 +
                                 w * (-5.83357013379057348645e-02 + w * -3.65315727442169155270e-02))));
  return hi - ((z * (s1 + s2) - lo) - z);
}

// atan2 with the quadrants of ::atan2 (sign of y, also of y = -0) from atan(min(|x|, |y|) / max(|x|, |y|)).
inline Pack atan2(const Pack& y, const Pack& x) {
  const Pack ax = abs(x), ay = abs(y);
  const Mask steep = ay > ax;
  const Pack big = select(steep, ay, ax), small = select(steep, ax, ay);
  const Pack t = select(big > Pack(0.0), small / big, 0.0);
  Pack r = atanUnit(t);
  const double pio2Hi = 1.57079632679489655800e+00, pio2Lo = 6.12323399573676603587e-17;
  const double piHi = 3.1415926535897931160e+00, piLo = 1.2246467991473531772e-16;
  r = select(steep, pio2Hi - (r - pio2Lo), r);
  r = select(x < Pack(0.0), piHi - (r - piLo), r);
  return Pack::fromBits((VecI)r.v | ((VecI)y.v & kSignBit));  // r >= 0: give it y's sign
}

}  // namespace simd
SOMICAGE_ISA_END
}  // namespace somicage

#endif  // SOMICAGE_SIMD_PACKS

// Forward-mode dual numbers: a value and its gradient with respect to N inputs, carried through the closed-form
// integrals (triangle_integrals_kernel.h, edge_integrals) so that the gradient of every coordinate column with
// respect to the query point is exact to rounding (the deformation gradient of jacobian.h), not a finite difference.
// Plain C++ (SOMICAGE_HD) so the templated kernels stay compilable by nvcc; the math functions live in
// somicage::dual and are found by argument-dependent lookup, so `sqrt(x)` in a template picks ::sqrt for doubles.
// The value type T is double, or simd::Pack (simd_pack.h) for kLanes points at once: the gradients' pack kernel
// (coordinate_gradients.cpp). Comparisons then give the pack's lane mask, and select blends lane by lane.
#pragma once

#include <math.h>

#include <type_traits>

#include "base/portable.h"

namespace somicage {
namespace dual {

template <int N, typename T = double>
struct Dual {
  T v;     // value
  T g[N];  // gradient with respect to the N seeded inputs

  SOMICAGE_HD Dual(const T& value = T(0)) : v(value) {  // NOLINT: implicit, so constants mix with duals
    for (int i = 0; i < N; ++i) g[i] = T(0);
  }
  // A double constant where the value is a pack (for doubles the constructor above is the one).
  template <typename U = T, typename = typename std::enable_if<!std::is_same<U, double>::value>::type>
  SOMICAGE_HD Dual(double value) : Dual(T(value)) {}  // NOLINT: implicit, as above
  // The input number `index` with value `value`: its gradient is the unit vector e_index.
  SOMICAGE_HD static Dual variable(const T& value, int index) {
    Dual d(value);
    d.g[index] = T(1);
    return d;
  }
  SOMICAGE_HD Dual& operator+=(const Dual& o) {
    v += o.v;
    for (int i = 0; i < N; ++i) g[i] += o.g[i];
    return *this;
  }
  SOMICAGE_HD Dual& operator-=(const Dual& o) {
    v -= o.v;
    for (int i = 0; i < N; ++i) g[i] -= o.g[i];
    return *this;
  }
  SOMICAGE_HD Dual& operator*=(const Dual& o) {
    for (int i = 0; i < N; ++i) g[i] = g[i] * o.v + v * o.g[i];
    v *= o.v;
    return *this;
  }
  SOMICAGE_HD Dual& operator/=(const Dual& o) {
    const T inv = 1 / o.v, q = v * inv;
    for (int i = 0; i < N; ++i) g[i] = (g[i] - q * o.g[i]) * inv;
    v = q;
    return *this;
  }
};

// f(x) with f'(x) = slope: the chain rule.
template <int N, typename T, typename Slope>
SOMICAGE_HD inline Dual<N, T> chain(const Dual<N, T>& x, const T& value, const Slope& slope) {
  Dual<N, T> r(value);
  for (int i = 0; i < N; ++i) r.g[i] = slope * x.g[i];
  return r;
}

template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator-(const Dual<N, T>& a) {
  return chain(a, T(-a.v), -1.0);
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator+(Dual<N, T> a, const Dual<N, T>& b) {
  return a += b;
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator-(Dual<N, T> a, const Dual<N, T>& b) {
  return a -= b;
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator*(Dual<N, T> a, const Dual<N, T>& b) {
  return a *= b;
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator/(Dual<N, T> a, const Dual<N, T>& b) {
  return a /= b;
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator+(Dual<N, T> a, double b) {
  a.v += b;
  return a;
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator+(double a, Dual<N, T> b) {
  b.v += a;
  return b;
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator-(Dual<N, T> a, double b) {
  a.v -= b;
  return a;
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator-(double a, const Dual<N, T>& b) {
  return chain(b, T(a - b.v), -1.0);
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator*(const Dual<N, T>& a, double b) {
  return chain(a, T(a.v * b), b);
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator*(double a, const Dual<N, T>& b) {
  return chain(b, T(a * b.v), a);
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator/(const Dual<N, T>& a, double b) {
  return chain(a, T(a.v / b), 1 / b);
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> operator/(double a, const Dual<N, T>& b) {
  const T q = a / b.v;
  return chain(b, q, T(-q / b.v));
}

// Comparisons look at values only: branches in the kernels pick the formula, the gradient is that formula's. For
// packs the result is the lane mask (branch_select.h takes each lane's branch).
#define SOMICAGE_DUAL_COMPARISON(OP)                                                                       \
  template <int N, typename T>                                                                             \
  SOMICAGE_HD inline auto operator OP(const Dual<N, T>& a, const Dual<N, T>& b)->decltype(a.v OP b.v) { \
    return a.v OP b.v;                                                                                     \
  }                                                                                                        \
  template <int N, typename T>                                                                             \
  SOMICAGE_HD inline auto operator OP(const Dual<N, T>& a, double b)->decltype(a.v OP T(b)) {           \
    return a.v OP T(b);                                                                                    \
  }                                                                                                        \
  template <int N, typename T>                                                                             \
  SOMICAGE_HD inline auto operator OP(double a, const Dual<N, T>& b)->decltype(T(a) OP b.v) {           \
    return T(a) OP b.v;                                                                                    \
  }
SOMICAGE_DUAL_COMPARISON(<)
SOMICAGE_DUAL_COMPARISON(<=)
SOMICAGE_DUAL_COMPARISON(>)
SOMICAGE_DUAL_COMPARISON(>=)
SOMICAGE_DUAL_COMPARISON(==)
SOMICAGE_DUAL_COMPARISON(!=)
#undef SOMICAGE_DUAL_COMPARISON

// m ? a : b lane by lane for duals whose values are packs (the mask type and select are simd_pack.h's).
template <typename Mask, int N, typename T>
inline Dual<N, T> select(const Mask& m, const Dual<N, T>& a, const Dual<N, T>& b) {
  Dual<N, T> r(select(m, a.v, b.v));
  for (int i = 0; i < N; ++i) r.g[i] = select(m, a.g[i], b.g[i]);
  return r;
}

// The value's function is ::f for doubles, found by argument-dependent lookup for packs (simd_math.h).
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> sqrt(const Dual<N, T>& x) {
  using ::sqrt;
  const T s = sqrt(x.v);
  return chain(x, s, T(0.5 / s));
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> log(const Dual<N, T>& x) {
  using ::log;
  return chain(x, T(log(x.v)), T(1 / x.v));
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> log1p(const Dual<N, T>& x) {
  using ::log1p;
  return chain(x, T(log1p(x.v)), T(1 / (1 + x.v)));
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> atan(const Dual<N, T>& x) {
  using ::atan;
  return chain(x, T(atan(x.v)), T(1 / (1 + x.v * x.v)));
}
template <int N, typename T>
SOMICAGE_HD inline Dual<N, T> atan2(const Dual<N, T>& y, const Dual<N, T>& x) {
  using ::atan2;
  // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
  const T inv = 1 / (x.v * x.v + y.v * y.v);
  Dual<N, T> r(atan2(y.v, x.v));
  for (int i = 0; i < N; ++i) r.g[i] = (x.v * y.g[i] - y.v * x.g[i]) * inv;
  return r;
}
template <int N>
SOMICAGE_HD inline Dual<N> sin(const Dual<N>& x) {
  return chain(x, ::sin(x.v), ::cos(x.v));
}
template <int N>
SOMICAGE_HD inline Dual<N> asin(const Dual<N>& x) {
  return chain(x, ::asin(x.v), 1 / ::sqrt(1 - x.v * x.v));
}
template <int N>
SOMICAGE_HD inline Dual<N> abs(const Dual<N>& x) {
  return x.v < 0 ? -x : x;
}
template <int N>
SOMICAGE_HD inline Dual<N> fabs(const Dual<N>& x) {
  return abs(x);
}

}  // namespace dual

// min and max for code templated on double or a dual (std::min needs one type): the chosen argument, gradient
// included.
template <typename Scalar>
SOMICAGE_HD inline Scalar smaller(const Scalar& a, const Scalar& b) {
  return b < a ? b : a;
}
template <typename Scalar>
SOMICAGE_HD inline Scalar larger(const Scalar& a, const Scalar& b) {
  return a < b ? b : a;
}

// The value of a double or a dual number, for code templated on either.
SOMICAGE_HD inline double valueOf(double x) { return x; }
template <int N>
SOMICAGE_HD inline double valueOf(const dual::Dual<N>& x) {
  return x.v;
}

}  // namespace somicage

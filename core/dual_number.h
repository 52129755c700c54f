// Forward-mode dual numbers: a value and its gradient with respect to N inputs, carried through the closed-form
// integrals (triangle_integrals_kernel.h, edge_integrals) so that the gradient of every coordinate column with
// respect to the query point is exact to rounding (the deformation gradient of jacobian.h), not a finite difference.
// Plain C++ (SOMICAGE_HD) so the templated kernels stay compilable by nvcc; the math functions live in
// somicage::dual and are found by argument-dependent lookup, so `sqrt(x)` in a template picks ::sqrt for doubles.
#pragma once

#include <math.h>

#include "portable.h"

namespace somicage {
namespace dual {

template <int N>
struct Dual {
  double v;     // value
  double g[N];  // gradient with respect to the N seeded inputs

  SOMICAGE_HD Dual(double value = 0) : v(value) {  // NOLINT: implicit, so constants mix with duals
    for (int i = 0; i < N; ++i) g[i] = 0;
  }
  // The input number `index` with value `value`: its gradient is the unit vector e_index.
  SOMICAGE_HD static Dual variable(double value, int index) {
    Dual d(value);
    d.g[index] = 1;
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
    const double inv = 1 / o.v, q = v * inv;
    for (int i = 0; i < N; ++i) g[i] = (g[i] - q * o.g[i]) * inv;
    v = q;
    return *this;
  }
};

// f(x) with f'(x) = slope: the chain rule.
template <int N>
SOMICAGE_HD inline Dual<N> chain(const Dual<N>& x, double value, double slope) {
  Dual<N> r(value);
  for (int i = 0; i < N; ++i) r.g[i] = slope * x.g[i];
  return r;
}

template <int N>
SOMICAGE_HD inline Dual<N> operator-(const Dual<N>& a) {
  return chain(a, -a.v, -1.0);
}
template <int N>
SOMICAGE_HD inline Dual<N> operator+(Dual<N> a, const Dual<N>& b) {
  return a += b;
}
template <int N>
SOMICAGE_HD inline Dual<N> operator-(Dual<N> a, const Dual<N>& b) {
  return a -= b;
}
template <int N>
SOMICAGE_HD inline Dual<N> operator*(Dual<N> a, const Dual<N>& b) {
  return a *= b;
}
template <int N>
SOMICAGE_HD inline Dual<N> operator/(Dual<N> a, const Dual<N>& b) {
  return a /= b;
}
template <int N>
SOMICAGE_HD inline Dual<N> operator+(Dual<N> a, double b) {
  a.v += b;
  return a;
}
template <int N>
SOMICAGE_HD inline Dual<N> operator+(double a, Dual<N> b) {
  b.v += a;
  return b;
}
template <int N>
SOMICAGE_HD inline Dual<N> operator-(Dual<N> a, double b) {
  a.v -= b;
  return a;
}
template <int N>
SOMICAGE_HD inline Dual<N> operator-(double a, const Dual<N>& b) {
  return chain(b, a - b.v, -1.0);
}
template <int N>
SOMICAGE_HD inline Dual<N> operator*(const Dual<N>& a, double b) {
  return chain(a, a.v * b, b);
}
template <int N>
SOMICAGE_HD inline Dual<N> operator*(double a, const Dual<N>& b) {
  return chain(b, a * b.v, a);
}
template <int N>
SOMICAGE_HD inline Dual<N> operator/(const Dual<N>& a, double b) {
  return chain(a, a.v / b, 1 / b);
}
template <int N>
SOMICAGE_HD inline Dual<N> operator/(double a, const Dual<N>& b) {
  const double q = a / b.v;
  return chain(b, q, -q / b.v);
}

// Comparisons look at values only: branches in the kernels pick the formula, the gradient is that formula's.
#define SOMICAGE_DUAL_COMPARISON(OP)                                        \
  template <int N>                                                          \
  SOMICAGE_HD inline bool operator OP(const Dual<N>& a, const Dual<N>& b) { \
    return a.v OP b.v;                                                      \
  }                                                                         \
  template <int N>                                                          \
  SOMICAGE_HD inline bool operator OP(const Dual<N>& a, double b) {         \
    return a.v OP b;                                                        \
  }                                                                         \
  template <int N>                                                          \
  SOMICAGE_HD inline bool operator OP(double a, const Dual<N>& b) {         \
    return a OP b.v;                                                        \
  }
SOMICAGE_DUAL_COMPARISON(<)
SOMICAGE_DUAL_COMPARISON(<=)
SOMICAGE_DUAL_COMPARISON(>)
SOMICAGE_DUAL_COMPARISON(>=)
SOMICAGE_DUAL_COMPARISON(==)
SOMICAGE_DUAL_COMPARISON(!=)
#undef SOMICAGE_DUAL_COMPARISON

template <int N>
SOMICAGE_HD inline Dual<N> sqrt(const Dual<N>& x) {
  const double s = ::sqrt(x.v);
  return chain(x, s, 0.5 / s);
}
template <int N>
SOMICAGE_HD inline Dual<N> log(const Dual<N>& x) {
  return chain(x, ::log(x.v), 1 / x.v);
}
template <int N>
SOMICAGE_HD inline Dual<N> log1p(const Dual<N>& x) {
  return chain(x, ::log1p(x.v), 1 / (1 + x.v));
}
template <int N>
SOMICAGE_HD inline Dual<N> atan(const Dual<N>& x) {
  return chain(x, ::atan(x.v), 1 / (1 + x.v * x.v));
}
template <int N>
SOMICAGE_HD inline Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
  // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
  const double inv = 1 / (x.v * x.v + y.v * y.v);
  Dual<N> r(::atan2(y.v, x.v));
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

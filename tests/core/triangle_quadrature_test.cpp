// The paper's quadrature baseline (core/geometry/triangle_quadrature.h): the 1D rule is exact where it must be, the
// triangle rule converges to the closed form away from the face, and it is visibly wrong near the face, which
// is why the closed form is the default.
#include "geometry/triangle_quadrature.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "geometry/triangle_integrals.h"

namespace somicage {
namespace {

using Vec3 = Eigen::Vector3d;

TEST(TriangleQuadrature, GaussLegendreIsExactForPolynomials) {
  for (int count : {1, 2, 3, 4, 5, 8, 13, 20, 50, 101, 200}) {
    Eigen::VectorXd z, w;
    gaussLegendre01(count, z, w);
    ASSERT_EQ(z.size(), count);
    ASSERT_EQ(w.size(), count);
    double worstSymmetry = 0;
    for (int i = 0; i < count; ++i) {
      EXPECT_GT(z(i), 0);
      EXPECT_LT(z(i), 1);
      EXPECT_GT(w(i), 0);
      if (i > 0) {
        EXPECT_GT(z(i), z(i - 1));
      }
      worstSymmetry =
          std::max(worstSymmetry, std::abs(z(i) + z(count - 1 - i) - 1) + std::abs(w(i) - w(count - 1 - i)));
    }
    EXPECT_LE(worstSymmetry, 1e-15) << count << " points: nodes and weights are symmetric about 1/2";
    // Exact for degree <= 2n - 1: int_0^1 x^d = 1/(d+1). High degrees are checked on (x - 1/2)^d, whose
    // integral 2^-d / (d + 1) (even d) avoids the cancellation of large monomial weights.
    double worst = 0;
    for (int d = 0; d <= std::min(2 * count - 1, 60); ++d) {
      double sum = 0;
      for (int i = 0; i < count; ++i) sum += w(i) * std::pow(z(i) - 0.5, d);
      const double exact = d % 2 ? 0.0 : std::pow(0.5, d) / (d + 1);
      worst = std::max(worst, std::abs(sum - exact) / std::pow(0.5, d));
    }
    EXPECT_LE(worst, 1e-14) << count << " points: worst error relative to 2^-d";
  }
}

// A random diameter-1 triangle (every 4th skinny, aspect up to about 50) and its unit normal.
struct Tri {
  Vec3 p[3], n;
};

Tri randomTriangle(std::mt19937_64& rng, bool skinny) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g;
  for (;;) {
    Tri t;
    for (auto& c : t.p) c = Vec3(u(rng), u(rng), u(rng));
    if (skinny) t.p[2] = 0.5 * (t.p[0] + t.p[1]) + (0.06 + 0.04 * u(rng)) * Vec3(g(rng), g(rng), g(rng));
    double diam = 0;
    for (int i = 0; i < 3; ++i) diam = std::max(diam, (t.p[i] - t.p[(i + 1) % 3]).norm());
    const Vec3 cr = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]);
    if (cr.norm() <= 1e-3 * diam * diam) continue;
    for (auto& c : t.p) c /= diam;
    t.n = cr.normalized();
    return t;
  }
}

// Stacked relative error of all outputs; D, V, B and W against ||V|| as in triangle_integrals_test.cpp.
double relativeError(const TriangleIntegrals& a, const TriangleIntegrals& ref) {
  double nV = 0, dT = 0;
  for (int k = 0; k < 3; ++k) {
    nV += ref.V[k].squaredNorm();
    dT += (a.D[k] - ref.D[k]) * (a.D[k] - ref.D[k]) + (a.V[k] - ref.V[k]).squaredNorm() +
          (a.B[k] - ref.B[k]).squaredNorm();
  }
  dT += (a.solidAngle - ref.solidAngle) * (a.solidAngle - ref.solidAngle);
  return std::max({std::abs(a.S - ref.S) / std::abs(ref.S), (a.M - ref.M).norm() / ref.M.norm(), std::sqrt(dT / nV)});
}

TriangleIntegrals closedForm(const Tri& t, const Vec3& x) {
  TriangleIntegrals I;
  integrateTriangle(makeTriangleFrame(t.p[0], t.p[1], t.p[2]), x, I);
  return I;
}

TriangleIntegrals gauss(const Tri& t, const Vec3& x, int n) {
  TriangleIntegrals I;
  integrateTriangleGauss(t.p[0], t.p[1], t.p[2], x, n, I);
  return I;
}

TEST(TriangleQuadrature, ConvergesToClosedFormAwayFromTheFace) {
  // Points 0.5 diameters from the triangle: above an interior point, and off a corner along a direction that
  // makes an obtuse angle with the whole triangle (so that the corner is the nearest point).
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> u(0, 1);
  double worst20 = 0, worst4 = 0;
  for (int it = 0; it < 16; ++it) {
    const Tri t = randomTriangle(rng, it % 4 == 3);
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vec3 foot = (1 - a - b) * t.p[0] + a * t.p[1] + b * t.p[2];
    const int k = it % 3;
    const Vec3 away = -((t.p[(k + 1) % 3] - t.p[k]).normalized() + (t.p[(k + 2) % 3] - t.p[k]).normalized());
    const double sgn = it % 2 ? 1.0 : -1.0;
    for (const Vec3& x :
         {Vec3(foot + 0.5 * sgn * t.n), Vec3(t.p[k] + 0.5 * (away.normalized() + sgn * t.n).normalized())}) {
      const TriangleIntegrals exact = closedForm(t, x);
      worst20 = std::max(worst20, relativeError(gauss(t, x, 20), exact));
      worst4 = std::max(worst4, relativeError(gauss(t, x, 4), exact));
    }
  }
  std::printf("  0.5 diameters away: worst relative error N = 4: %.1e, N = 20: %.1e\n", worst4, worst20);
  EXPECT_LE(worst20, 1e-10) << "N = 20 (1200 points), relative error";
  EXPECT_GT(worst4, worst20) << "the rule converges with N";
}

TEST(TriangleQuadrature, InaccurateNearTheFace) {
  // 1e-4 diameters above an interior point the integrand is nearly singular; the paper's rule misses it badly
  // even with 7500 points, while the closed form is exact to round-off (triangle_integrals_test.cpp).
  std::mt19937_64 rng(92);
  std::uniform_real_distribution<double> u(0, 1);
  for (int n : {20, 50}) {
    double best = 1e300;
    for (int it = 0; it < 8; ++it) {
      const Tri t = randomTriangle(rng, it % 4 == 3);
      double a = u(rng), b = u(rng);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      const Vec3 x = (1 - a - b) * t.p[0] + a * t.p[1] + b * t.p[2] + 1e-4 * t.n;
      best = std::min(best, relativeError(gauss(t, x, n), closedForm(t, x)));
    }
    std::printf("  1e-4 above the face, N = %d: smallest relative error %.1e\n", n, best);
    EXPECT_GT(best, 1e-3) << "N = " << n << ": smallest relative error of the Gauss rule at distance 1e-4";
  }
}

TEST(TriangleQuadrature, SolidAngleAndDegenerateFaces) {
  // The solid angle is int h / R^3 with h = n.(x - p0): positive on the outward side.
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  TriangleIntegrals I;
  integrateTriangleGauss(p0, p1, p2, Vec3(0.2, 0.2, 2), 30, I);
  const Tri t{{p0, p1, p2}, Vec3(0, 0, 1)};
  EXPECT_NEAR(I.solidAngle, closedForm(t, Vec3(0.2, 0.2, 2)).solidAngle, 1e-14);
  EXPECT_GT(I.solidAngle, 0);
  integrateTriangleGauss(p0, p1, 0.5 * (p0 + p1), Vec3(0.2, 0.2, 2), 10, I);
  EXPECT_EQ(I.S, 0) << "zero-area faces contribute nothing";
  EXPECT_EQ(I.M.norm() + I.B[0].norm() + I.V[1].norm() + std::abs(I.D[2]) + std::abs(I.solidAngle), 0);
}

}  // namespace
}  // namespace somicage

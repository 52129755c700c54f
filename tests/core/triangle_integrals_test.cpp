// Closed-form triangle integrals (core/geometry/triangle_integrals.h) against an independent adaptive quadrature, plus
// the identities of shared docs/closed-form.md section 4, the cube's solid angle and extreme scales.
//
// Golden data: an adaptive high-order quadrature written here (the same construction as the reference in
// shared reference/closed-form/closedform.py): it shares no formula with the closed form, only the 1D
// Gauss-Legendre rule, which triangle_quadrature_test.cpp checks for polynomial exactness.
#include "geometry/triangle_integrals.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "geometry/triangle_quadrature.h"

namespace somicage {
namespace {

using Vec3 = Eigen::Vector3d;

// ---------------------------------------------------------------------------------------------------------------
// Reference: split the triangle into 4 until every piece is at least one piece-diameter away from x, then apply an
// nq x nq collapsed (Duffy) Gauss-Legendre rule per piece. Both methods get the triangle in the frame centred at
// x, so that the reference does not lose eps/distance by building its pieces in absolute coordinates.
// ---------------------------------------------------------------------------------------------------------------

struct ReferenceRule {
  std::vector<double> lam[3], weight;  // barycentric coordinates and weights (summing to 1) on a triangle
};

const ReferenceRule& collapsedGauss14() {
  static const ReferenceRule rule = [] {
    ReferenceRule r;
    Eigen::VectorXd z, w;
    gaussLegendre01(14, z, w);
    for (int i = 0; i < 14; ++i)
      for (int j = 0; j < 14; ++j) {
        const double u = z(i), v = z(i) * z(j);  // (u, u v) covers the triangle with Jacobian u
        r.lam[0].push_back(1 - u), r.lam[1].push_back(u - v), r.lam[2].push_back(v);
        r.weight.push_back(2 * w(i) * w(j) * u);
      }
    return r;
  }();
  return rule;
}

// Same outputs as integrateTriangle() for the triangle P (already relative to x) and x = 0.
TriangleIntegrals referenceIntegrals(const Vec3 P[3]) {
  struct Piece {
    Vec3 p[3];
    Vec3 bary[3];  // barycentric coordinates of the piece's corners in the original triangle
  };
  const Vec3 n = (P[1] - P[0]).cross(P[2] - P[0]).normalized();
  const ReferenceRule& rule = collapsedGauss14();
  // Symmetric 3x3 matrices are accumulated as (xx, xy, xz, yy, yz, zz).
  long double S = 0, W = 0, M[6] = {}, D[3] = {}, V[3][3] = {}, B[3][6] = {};

  std::vector<Piece> todo = {{{P[0], P[1], P[2]}, {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}}};
  long pieces = 0;
  while (!todo.empty()) {
    const Piece piece = todo.back();
    todo.pop_back();
    const Vec3 centre = (piece.p[0] + piece.p[1] + piece.p[2]) / 3;
    double radius = 0, diam = 0;
    for (int i = 0; i < 3; ++i) {
      radius = std::max(radius, (piece.p[i] - centre).norm());
      diam = std::max(diam, (piece.p[i] - piece.p[(i + 1) % 3]).norm());
    }
    if (centre.norm() - radius < diam) {
      Vec3 mid[3], midBary[3];
      for (int i = 0; i < 3; ++i) {
        mid[i] = 0.5 * (piece.p[i] + piece.p[(i + 1) % 3]);
        midBary[i] = 0.5 * (piece.bary[i] + piece.bary[(i + 1) % 3]);
      }
      todo.push_back({{piece.p[0], mid[0], mid[2]}, {piece.bary[0], midBary[0], midBary[2]}});
      todo.push_back({{mid[0], piece.p[1], mid[1]}, {midBary[0], piece.bary[1], midBary[1]}});
      todo.push_back({{mid[2], mid[1], piece.p[2]}, {midBary[2], midBary[1], piece.bary[2]}});
      todo.push_back({{mid[0], mid[1], mid[2]}, {midBary[0], midBary[1], midBary[2]}});
      continue;
    }
    ++pieces;
    const double area = 0.5 * (piece.p[1] - piece.p[0]).cross(piece.p[2] - piece.p[0]).norm();
    // Sum each piece in double, then add the piece totals in extended precision.
    double s = 0, solid = 0, m[6] = {}, d[3] = {}, v[3][3] = {}, b[3][6] = {};
    for (size_t q = 0; q < rule.weight.size(); ++q) {
      const double l0 = rule.lam[0][q], l1 = rule.lam[1][q], l2 = rule.lam[2][q];
      const Vec3 r = l0 * piece.p[0] + l1 * piece.p[1] + l2 * piece.p[2];
      const Vec3 phi = l0 * piece.bary[0] + l1 * piece.bary[1] + l2 * piece.bary[2];
      const double w = area * rule.weight[q];
      const double R2 = r.squaredNorm(), R = std::sqrt(R2), iR3 = 1 / (R * R2), iR5 = iR3 / R2, nr = n.dot(r);
      const double rr[6] = {r[0] * r[0], r[0] * r[1], r[0] * r[2], r[1] * r[1], r[1] * r[2], r[2] * r[2]};
      s += w / R;
      solid -= w * nr * iR3;  // h = -n.r on the face
      for (int a = 0; a < 6; ++a) m[a] += w * iR3 * rr[a];
      for (int k = 0; k < 3; ++k) {
        const double wk3 = w * phi[k] * iR3, wk5 = w * phi[k] * nr * iR5;
        d[k] += wk3 * nr;
        for (int i = 0; i < 3; ++i) v[k][i] += wk3 * r[i];
        for (int a = 0; a < 6; ++a) b[k][a] += wk5 * rr[a];
      }
    }
    S += s, W += solid;
    for (int a = 0; a < 6; ++a) M[a] += m[a];
    for (int k = 0; k < 3; ++k) {
      D[k] += d[k];
      for (int i = 0; i < 3; ++i) V[k][i] += v[k][i];
      for (int a = 0; a < 6; ++a) B[k][a] += b[k][a];
    }
  }
  EXPECT_LT(pieces, 200000) << "reference quadrature refined more than expected";
  auto symmetric = [](const long double x[6]) {
    Eigen::Matrix3d out;
    out << double(x[0]), double(x[1]), double(x[2]), double(x[1]), double(x[3]), double(x[4]), double(x[2]),
        double(x[4]), double(x[5]);
    return out;
  };
  TriangleIntegrals out;
  out.S = static_cast<double>(S);
  out.solidAngle = static_cast<double>(W);
  out.M = symmetric(M);
  for (int k = 0; k < 3; ++k) {
    out.D[k] = static_cast<double>(D[k]);
    for (int i = 0; i < 3; ++i) out.V[k][i] = static_cast<double>(V[k][i]);
    out.B[k] = symmetric(B[k]);
  }
  return out;
}

// ---------------------------------------------------------------------------------------------------------------
// Error measures (as in docs/closed-form.md section 7): S and M relative; D, V, B and W against ||V||, because D,
// B and W vanish linearly with the height and have no meaningful relative error in the plane.
// ---------------------------------------------------------------------------------------------------------------

struct Errors {
  double S = 0, M = 0, D = 0, V = 0, B = 0, W = 0;
  double max() const { return std::max({S, M, D, V, B, W}); }
  void takeMax(const Errors& e) {
    S = std::max(S, e.S), M = std::max(M, e.M), D = std::max(D, e.D);
    V = std::max(V, e.V), B = std::max(B, e.B), W = std::max(W, e.W);
  }
  std::string str() const {
    char buf[200];
    std::snprintf(buf, sizeof buf, "S %.1e  M %.1e  D %.1e  V %.1e  B %.1e  W %.1e", S, M, D, V, B, W);
    return buf;
  }
};

double normV(const TriangleIntegrals& I) {
  return std::sqrt(I.V[0].squaredNorm() + I.V[1].squaredNorm() + I.V[2].squaredNorm());
}

// relative = false: plain absolute differences (far field, diameter-1 triangles).
Errors compare(const TriangleIntegrals& a, const TriangleIntegrals& ref, bool relative) {
  Errors e;
  const double sV = relative ? normV(ref) : 1.0;
  double dD = 0, dV = 0, dB = 0;
  for (int k = 0; k < 3; ++k) {
    dD += (a.D[k] - ref.D[k]) * (a.D[k] - ref.D[k]);
    dV += (a.V[k] - ref.V[k]).squaredNorm();
    dB += (a.B[k] - ref.B[k]).squaredNorm();
  }
  e.S = std::abs(a.S - ref.S) / (relative ? std::abs(ref.S) : 1.0);
  e.M = (a.M - ref.M).norm() / (relative ? ref.M.norm() : 1.0);
  e.D = std::sqrt(dD) / sV, e.V = std::sqrt(dV) / sV, e.B = std::sqrt(dB) / sV;
  e.W = std::abs(a.solidAngle - ref.solidAngle) / sV;
  return e;
}

// ---------------------------------------------------------------------------------------------------------------
// Random triangles of diameter 1 and query points, as in closedform.py (random_triangle, sample_point).
// ---------------------------------------------------------------------------------------------------------------

struct TestTriangle {
  Vec3 p[3];
  Vec3 n, tau[3], m[3];  // unit normal; per edge e (p_e -> p_{e+1}): direction and outward in-plane normal
};

TestTriangle makeTestTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  TestTriangle t{{p0, p1, p2}, {}, {}, {}};
  t.n = (p1 - p0).cross(p2 - p0).normalized();
  for (int e = 0; e < 3; ++e) {
    t.tau[e] = (t.p[(e + 1) % 3] - t.p[e]).normalized();
    t.m[e] = t.tau[e].cross(t.n);
  }
  return t;
}

class Sampler {
 public:
  explicit Sampler(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int count) { return std::uniform_int_distribution<int>(0, count - 1)(rng_); }
  double sign() { return integer(2) ? 1.0 : -1.0; }
  Vec3 normal3() {
    std::normal_distribution<double> g;
    return Vec3(g(rng_), g(rng_), g(rng_));
  }
  Vec3 barycentric() {  // uniform on the triangle
    double a = uniform(0, 1), b = uniform(0, 1);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    return Vec3(1 - a - b, a, b);
  }

  // Generic, or skinny (third corner close to the first edge's midpoint, aspect ratio up to about 50).
  TestTriangle triangle(bool skinny) {
    for (;;) {
      Vec3 p[3];
      for (auto& c : p) c = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      if (skinny) p[2] = 0.5 * (p[0] + p[1]) + uniform(0.02, 0.1) * normal3();
      double diam = 0;
      for (int i = 0; i < 3; ++i) diam = std::max(diam, (p[i] - p[(i + 1) % 3]).norm());
      if ((p[1] - p[0]).cross(p[2] - p[0]).norm() > 1e-3 * diam * diam)
        return makeTestTriangle(p[0] / diam, p[1] / diam, p[2] / diam);
    }
  }

  Vec3 point(const TestTriangle& t, const std::string& where, double dist) {
    const Vec3 lam = barycentric();
    const double sgn = sign();
    if (where == "interior") return lam[0] * t.p[0] + lam[1] * t.p[1] + lam[2] * t.p[2] + sgn * dist * t.n;
    if (where == "edge") {  // above a point on an edge, slightly inside or outside
      const int e = integer(3);
      const double s = uniform(0.05, 0.95);
      const Vec3 q = (1 - s) * t.p[e] + s * t.p[(e + 1) % 3];
      return q + uniform(-1, 1) * dist * t.m[e] + sgn * dist * t.n;
    }
    if (where == "vertex") {
      const int v = integer(3);
      Vec3 dir = normal3();
      dir = (dir - dir.dot(t.n) * t.n).normalized();
      return t.p[v] + dist * uniform(0, 1) * dir + sgn * dist * t.n;
    }
    if (where == "edgeline") {  // near the extension of an edge's supporting line, beyond a corner
      const int e = integer(3);
      const Vec3 q = t.p[(e + 1) % 3] + uniform(0.01, 0.5) * t.tau[e];
      return q + dist * sgn * t.n + dist * uniform(-1, 1) * t.m[e];
    }
    if (where == "inplane") {  // in the plane (h ~ 1e-16 after rounding), outside, near an edge
      const int e = integer(3);
      const double s = uniform(0.05, 0.95);
      return (1 - s) * t.p[e] + s * t.p[(e + 1) % 3] + dist * t.m[e];
    }
    // "random" and "far": a random direction at the given distance from the centroid.
    return (t.p[0] + t.p[1] + t.p[2]) / 3 + dist * normal3().normalized();
  }

 private:
  std::mt19937_64 rng_;
};

TriangleIntegrals closedForm(const TestTriangle& t, const Vec3& x) {
  TriangleIntegrals I;
  integrateTriangle(makeTriangleFrame(t.p[0], t.p[1], t.p[2]), x, I);
  return I;
}

// ---------------------------------------------------------------------------------------------------------------
// Closed form vs reference, one row of docs/closed-form.md table A per case.
// ---------------------------------------------------------------------------------------------------------------

// Distance from x to the triangle's boundary (its three edges): the integrals are conditioned like diam / delta.
double distanceToBoundary(const TestTriangle& t, const Vec3& x) {
  double best = 1e300;
  for (int e = 0; e < 3; ++e) {
    const Vec3 a = t.p[e], ab = t.p[(e + 1) % 3] - a;
    const double s = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + s * ab - x).norm());
  }
  return best;
}

struct ReferenceCase {
  const char* where;
  double dist;
};

std::ostream& operator<<(std::ostream& os, const ReferenceCase& c) { return os << c.where << " " << c.dist; }

class TriangleIntegralsVsReference : public ::testing::TestWithParam<ReferenceCase> {};

// Tolerance (docs/closed-form.md sections 1, 5.6, 5.7 and tables A, B), relative, for diameter-1 triangles:
//   1e-12                      where the integrals are well conditioned;
//   + 4 eps / delta            at a distance delta from the boundary: there the exact integrals themselves move by
//                              about eps / delta when x moves by one ulp, and no double-precision algorithm can do
//                              better (table A: 6.6e-11 at delta = 1e-6);
//   + 4 eps (dist / h_min)^3   at a distance dist from the centroid of a face with smallest altitude h_min: the
//                              hat functions are expanded about the projection of x, whose barycentric coordinates
//                              grow like dist / h_min, so the edge sums cancel (skinny faces, points beyond them).
// "far" rows are measured in absolute terms (1e-13): the relative error of a distant face's tiny integrals grows
// with that cancellation (table A: 4e-8 at 100 diameters) while the absolute error stays at round-off.
constexpr double kWellConditioned = 1e-12, kConditionFactor = 4, kFarAbsolute = 1e-13;

TEST_P(TriangleIntegralsVsReference, MatchesAdaptiveQuadrature) {
  const ReferenceCase& c = GetParam();
  const bool far = std::string(c.where) == "far";
  Sampler sampler(1234 + static_cast<unsigned>(std::abs(std::log10(c.dist)) * 10) + c.where[0]);
  Errors worst;
  double worstRatio = 0;
  std::string worstAt;
  // 16 random triangles (4 skinny) with one point each: the deep near-field rows need thousands of pieces.
  const int triangles = 16, pointsPerTriangle = 1;
  for (int it = 0; it < triangles; ++it) {
    const TestTriangle t0 = sampler.triangle(it % 4 == 3);  // every 4th is skinny
    for (int ip = 0; ip < pointsPerTriangle; ++ip) {
      const Vec3 x = sampler.point(t0, c.where, c.dist);
      const double delta = distanceToBoundary(t0, x);
      const double hMin = (t0.p[1] - t0.p[0]).cross(t0.p[2] - t0.p[0]).norm();  // 2A / diam with diam = 1
      const double cancellation = std::pow((x - (t0.p[0] + t0.p[1] + t0.p[2]) / 3).norm() / hMin, 3);
      const double tol = far ? kFarAbsolute
                             : kWellConditioned + kConditionFactor * std::numeric_limits<double>::epsilon() *
                                                      (1 / delta + cancellation);
      const TestTriangle t = makeTestTriangle(t0.p[0] - x, t0.p[1] - x, t0.p[2] - x);
      const Errors e = compare(closedForm(t, Vec3::Zero()), referenceIntegrals(t.p), !far);
      if (e.max() / tol > worstRatio) {
        worstRatio = e.max() / tol;
        char buf[300];
        std::snprintf(buf, sizeof buf, "triangle %d%s, distance to its boundary %.1e, h_min %.1e: %s; tolerance %.1e",
                      it, it % 4 == 3 ? " (skinny)" : "", delta, hMin, e.str().c_str(), tol);
        worstAt = buf;
      }
      worst.takeMax(e);
    }
  }
  std::printf("  %-9s %7.0e  worst: %s\n", c.where, c.dist, worst.str().c_str());
  EXPECT_LE(worstRatio, 1.0) << "largest error relative to its tolerance, at " << worstAt;
}

INSTANTIATE_TEST_SUITE_P(
    Triangle, TriangleIntegralsVsReference,
    ::testing::Values(ReferenceCase{"interior", 1e-1}, ReferenceCase{"interior", 1e-2}, ReferenceCase{"interior", 1e-4},
                      ReferenceCase{"interior", 1e-6}, ReferenceCase{"edge", 1e-2}, ReferenceCase{"edge", 1e-4},
                      ReferenceCase{"edge", 1e-6}, ReferenceCase{"vertex", 1e-2}, ReferenceCase{"vertex", 1e-4},
                      ReferenceCase{"vertex", 1e-6}, ReferenceCase{"edgeline", 1e-2}, ReferenceCase{"edgeline", 1e-6},
                      ReferenceCase{"inplane", 1e-2}, ReferenceCase{"inplane", 1e-4}, ReferenceCase{"random", 0.5},
                      ReferenceCase{"far", 3}, ReferenceCase{"far", 10}, ReferenceCase{"far", 100}),
    [](const ::testing::TestParamInfo<ReferenceCase>& info) {
      return std::string(info.param.where) + "_" + std::to_string(info.index);
    });

// ---------------------------------------------------------------------------------------------------------------
// Identities of docs/closed-form.md section 4.
// ---------------------------------------------------------------------------------------------------------------

TEST(TriangleIntegrals, ConsistencyIdentities) {
  // D_k = n.V_k, trace B_k = D_k and sum_k D_k = -W, relative to ||V|| + |W| (D and B vanish in the plane).
  // Near the face (up to 0.3 diameters) they hold to round-off. At 5 diameters the edge sums cancel and the two
  // sides of each identity lose digits in different ways, like eps (D / h_min)^3 (closed-form.md section 5.7).
  Sampler sampler(77);
  struct Worst {
    double normal = 0, trace = 0, sum = 0;
  } nearField, farField;
  const char* wheres[] = {"interior", "edge", "vertex", "edgeline", "inplane", "far"};
  for (int it = 0; it < 16; ++it) {
    const TestTriangle t = sampler.triangle(it % 4 == 3);
    for (const char* where : wheres)
      for (double dist : {1e-6, 1e-3, 0.3, 5.0}) {
        const TriangleIntegrals I = closedForm(t, sampler.point(t, where, dist));
        const double scale = normV(I) + std::abs(I.solidAngle);
        Worst& w = dist > 1 ? farField : nearField;
        double sumD = 0;
        for (int k = 0; k < 3; ++k) {
          w.normal = std::max(w.normal, std::abs(I.D[k] - t.n.dot(I.V[k])) / scale);
          w.trace = std::max(w.trace, std::abs(I.B[k].trace() - I.D[k]) / scale);
          sumD += I.D[k];
        }
        w.sum = std::max(w.sum, std::abs(sumD + I.solidAngle) / scale);
      }
  }
  EXPECT_LE(nearField.normal, 1e-14) << "D_k = n.V_k near the face";
  EXPECT_LE(nearField.trace, 1e-13) << "trace B_k = D_k near the face";
  EXPECT_LE(nearField.sum, 1e-14) << "sum_k D_k = -W near the face";
  EXPECT_LE(farField.normal, 1e-14) << "D_k = n.V_k at 5 diameters";
  EXPECT_LE(farField.trace, 1e-11) << "trace B_k = D_k at 5 diameters";
  EXPECT_LE(farField.sum, 1e-13) << "sum_k D_k = -W at 5 diameters";
}

TEST(TriangleIntegrals, GradientOfVMatchesFiniteDifferences) {
  // grad_x V_k = (D_k I - 3 B_k) / h, checked by 4th-order central differences with step 1e-3 |h|.
  Sampler sampler(78);
  double worst = 0;
  for (int it = 0; it < 12; ++it) {
    const TestTriangle t = sampler.triangle(it % 4 == 3);
    const TriangleFrame frame = makeTriangleFrame(t.p[0], t.p[1], t.p[2]);
    for (const char* where : {"interior", "edge", "vertex", "far"}) {
      const Vec3 x = sampler.point(t, where, where == std::string("far") ? 1.0 : 0.2);
      const double h = t.n.dot(x - t.p[0]);
      if (std::abs(h) < 0.05) continue;  // the identity divides by h
      TriangleIntegrals I, Ip;
      integrateTriangle(frame, x, I);
      const double step = 1e-3 * std::abs(h);
      for (int k = 0; k < 3; ++k) {
        const Eigen::Matrix3d expected = (I.D[k] * Eigen::Matrix3d::Identity() - 3 * I.B[k]) / h;
        Eigen::Matrix3d fd;
        for (int j = 0; j < 3; ++j) {
          Vec3 col = Vec3::Zero();
          const double stencil[4][2] = {{-2, 1.0 / 12}, {-1, -8.0 / 12}, {1, 8.0 / 12}, {2, -1.0 / 12}};
          for (const auto& s : stencil) {
            integrateTriangle(frame, x + s[0] * step * Vec3::Unit(j), Ip);
            col += s[1] * Ip.V[k];
          }
          fd.col(j) = col / step;
        }
        worst = std::max(worst, (fd - expected).norm() / expected.norm());
      }
    }
  }
  EXPECT_LE(worst, 1e-8) << "relative Frobenius error of grad V_k";
}

// ---------------------------------------------------------------------------------------------------------------
// Solid angle of a closed surface: -4 pi inside (W is negative on the inward side), 0 outside.
// ---------------------------------------------------------------------------------------------------------------

TEST(TriangleIntegrals, CubeSolidAngle) {
  // Unit cube [0, 1]^3 with outward counter-clockwise triangles.
  const Vec3 c[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
  std::vector<TriangleFrame> frames;
  for (const auto& f : faces) frames.push_back(makeTriangleFrame(c[f[0]], c[f[1]], c[f[2]]));
  auto total = [&](const Vec3& x) {
    double w = 0;
    TriangleIntegrals I;
    for (const auto& frame : frames) {
      integrateTriangle(frame, x, I);
      w += I.solidAngle;
    }
    return w;
  };
  Sampler sampler(79);
  // Well-conditioned points: the centre, near faces but away from the triangles' edges, near a corner, far away.
  std::vector<Vec3> inside = {{0.5, 0.5, 0.5}, {0.7, 0.2, 1e-6}, {0.2, 0.7, 1 - 1e-9}, {1e-3, 1e-3, 1e-3}};
  std::vector<Vec3> outside = {{0.7, 0.2, -1e-6}, {2, 0.5, 0.5},   {-1e-3, -1e-3, -1e-3},
                               {1.5, 1.5, 0.5},   {0.5, 0.5, 100}, {2, 0.5, 0}};  // the last is in a face's plane
  for (int i = 0; i < 20; ++i) {
    inside.push_back(Vec3(sampler.uniform(0.01, 0.99), sampler.uniform(0.01, 0.99), sampler.uniform(0.01, 0.99)));
    const Vec3 far = sampler.normal3().normalized() * sampler.uniform(0.9, 10) + Vec3(0.5, 0.5, 0.5);
    if (((far.array() > -0.01) && (far.array() < 1.01)).all()) continue;
    outside.push_back(far);
  }
  double worstInside = 0, worstOutside = 0;
  for (const Vec3& x : inside) worstInside = std::max(worstInside, std::abs(total(x) + 4 * M_PI));
  for (const Vec3& x : outside) worstOutside = std::max(worstOutside, std::abs(total(x)));
  EXPECT_LE(worstInside, 1e-12) << "max |sum W + 4 pi| inside";
  EXPECT_LE(worstOutside, 1e-12) << "max |sum W| outside";

  // Within delta of an edge shared by two triangles each face's W is only known to about eps / delta (its
  // gradient is 1 / delta there, section 5.6), and the two faces round differently, so the sum is too.
  double worstRatio = 0;
  for (double delta : {1e-4, 1e-7, 1e-10}) {
    const double tol = 20 * std::numeric_limits<double>::epsilon() / delta;
    worstRatio = std::max(worstRatio, std::abs(total(Vec3(0.3, 0.3, delta)) + 4 * M_PI) / tol);    // face diagonal
    worstRatio = std::max(worstRatio, std::abs(total(Vec3(0.5, delta, delta)) + 4 * M_PI) / tol);  // cube edge
    worstRatio = std::max(worstRatio, std::abs(total(Vec3(0.3, 0.3, -delta))) / tol);
  }
  EXPECT_LE(worstRatio, 1.0) << "|sum W + 4 pi| inside or |sum W| outside near an edge, relative to 20 eps / delta";
}

// ---------------------------------------------------------------------------------------------------------------
// Extreme scales: scaling the triangle and x by s multiplies S and M by s and leaves D, V, B, W unchanged
// (all four are integrals of degree-0 homogeneous kernels over an area).
// ---------------------------------------------------------------------------------------------------------------

TEST(TriangleIntegrals, ExtremeScales) {
  Sampler sampler(80);
  for (double s : {1e-6, 1e6, 1e-8, 1e8}) {
    Errors worst;
    for (int it = 0; it < 12; ++it) {
      const TestTriangle t = sampler.triangle(it % 4 == 3);
      for (const char* where : {"interior", "edge", "vertex", "far"}) {
        const Vec3 x = sampler.point(t, where, where == std::string("far") ? 0.5 : 0.1);
        TriangleIntegrals ref = closedForm(t, x);
        ref.S *= s;
        ref.M *= s;
        const TestTriangle ts = makeTestTriangle(s * t.p[0], s * t.p[1], s * t.p[2]);
        worst.takeMax(compare(closedForm(ts, s * x), ref, true));
      }
    }
    EXPECT_LE(worst.max(), 1e-12) << "scale " << s << ": " << worst.str();
  }
}

TEST(TriangleIntegrals, DegenerateFaceContributesNothing) {
  const Vec3 a(0, 0, 0), b(1, 1, 1), mid(0.5, 0.5, 0.5);
  for (const TriangleFrame& f :
       {makeTriangleFrame(a, b, mid), makeTriangleFrame(a, a, b), makeTriangleFrame(a, a, a)}) {
    EXPECT_TRUE(f.degenerate);
    TriangleIntegrals I;
    integrateTriangle(f, Vec3(0.2, 0.7, -0.1), I);
    EXPECT_EQ(I.S, 0);
    EXPECT_EQ(I.solidAngle, 0);
    EXPECT_EQ(I.M.norm() + I.V[0].norm() + I.B[2].norm() + std::abs(I.D[1]), 0);
  }
  EXPECT_FALSE(makeTriangleFrame(a, Vec3(1, 0, 0), Vec3(0.5, 1e-6, 0)).degenerate);  // aspect 1e6 is still a face
}

}  // namespace
}  // namespace somicage

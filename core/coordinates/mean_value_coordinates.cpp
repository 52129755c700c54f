#include "coordinates/mean_value_coordinates.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/dual_eigen.h"
#include "base/errors.h"
#include "base/point_blocks.h"

namespace somicage {

namespace {

constexpr double kSnapToVertex = 1e-14;  // times the cage diameter
constexpr double kOnEdge2d = 1e-14;      // |sin alpha| below which a point with cos alpha < 0 is on the edge
constexpr double kOnFace3d = 1e-12;      // |height| / (distance to the nearest corner) below which x is on the face
constexpr double kNearPlane3d = 1e-3;    // |det[u0 u1 u2]| below which x' outside a face uses nearPlaneWeights

// ---------------------------------------------------------------------------------------------------------------
// 2D (Hormann & Floater 2006)
// ---------------------------------------------------------------------------------------------------------------

// Writes the coordinates of x into w (#V, zeroed by the caller). Scalar: double, or a dual number for the
// gradients (the formulas' own derivatives; branches are taken on values).
template <typename Scalar>
void meanValue2d(const Cage& cage, const Eigen::Matrix<Scalar, 2, 1>& x, double snap, Scalar* w) {
  using std::abs;
  using Vector = Eigen::Matrix<Scalar, 2, 1>;
  const int numVertices = cage.numVertices();
  std::vector<Vector> s(numVertices);
  std::vector<Scalar> r(numVertices);
  for (int i = 0; i < numVertices; ++i) {
    s[i] = cage.vertices.row(i).transpose().template cast<Scalar>() - x;
    r[i] = s[i].norm();
    if (r[i] <= snap) {
      w[i] = 1;
      return;
    }
  }
  Scalar total = 0;
  for (int j = 0; j < cage.numFaces(); ++j) {
    const int i0 = cage.faces(j, 0), i1 = cage.faces(j, 1);
    const Scalar twiceArea = s[i0].x() * s[i1].y() - s[i0].y() * s[i1].x();  // r0 r1 sin(alpha)
    const Scalar dot = s[i0].dot(s[i1]);                                     // r0 r1 cos(alpha)
    const Scalar rr = r[i0] * r[i1];
    if (abs(twiceArea) <= kOnEdge2d * rr && dot < 0) {  // x on the edge: linear interpolation
      std::fill(w, w + numVertices, Scalar(0.0));
      w[i0] = r[i1] / (r[i0] + r[i1]);
      w[i1] = r[i0] / (r[i0] + r[i1]);
      return;
    }
    // tan(alpha/2) = sin/(1 + cos) = (1 - cos)/sin: take the form whose denominator cannot cancel.
    const Scalar tanHalf = dot >= 0 ? twiceArea / (rr + dot) : (rr - dot) / twiceArea;
    w[i0] += tanHalf / r[i0];
    w[i1] += tanHalf / r[i1];
    total += tanHalf / r[i0] + tanHalf / r[i1];
  }
  if (total != 0)
    for (int i = 0; i < numVertices; ++i) w[i] /= total;
}

// ---------------------------------------------------------------------------------------------------------------
// 3D (Ju, Schaefer & Warren 2005)
// ---------------------------------------------------------------------------------------------------------------

struct MeanValueFace {
  int corner[3];
  Eigen::Vector3d n;               // unit outward normal
  Eigen::Vector3d tau[3], m[3];    // edge k = corner k -> k+1: unit direction, outward in-plane normal tau x n
  double length[3];                // edge lengths
  Eigen::Vector3d hatGradient[3];  // n x (p_{k+2} - p_{k+1}) = twiceArea * gradient of the hat of corner k
  double twiceArea = 0;
};

// c int_{sm}^{sp} ds / (s^2 + c^2) = atan(sp/c) - atan(sm/c), the angle the segment subtends from distance c.
template <typename Scalar>
Scalar subtendedAngle(const Scalar& c, const Scalar& sm, const Scalar& sp) {
  using std::atan2;
  return atan2(c * (sp - sm), c * c + sm * sp);
}

// int_{sm}^{sp} ds / (s^2 + c^2); the limit for c -> 0 when the segment does not contain s = 0.
template <typename Scalar>
Scalar inverseSquareIntegral(const Scalar& c, const Scalar& sm, const Scalar& sp) {
  return c > 0 ? subtendedAngle(c, sm, sp) / c : (sp - sm) / (sm * sp);
}

// K = a int_{sm}^{sp} ds / ((s^2 + a^2)(s^2 + b^2)) with b^2 = a^2 + h^2, h != 0. The partial fractions
// (F(a) - (a/b) F(b)) / h^2, F = subtendedAngle, cancel for small h; instead F(a) - F(b) is summed from
// atan(s/a) - atan(s/b) = atan(s (b - a) / (ab + s^2)) and 1 - a/b = h^2 / (b (a + b)), both exact.
template <typename Scalar>
Scalar nearPlaneEdgeTerm(const Scalar& a, const Scalar& h, const Scalar& sm, const Scalar& sp) {
  using std::atan, std::sqrt;
  const Scalar b = sqrt(a * a + h * h), delta = h * h / (a + b);
  auto atanDifference = [&](const Scalar& s) {
    const Scalar denominator = a * b + s * s;
    return denominator > 0 ? atan(s * delta / denominator) : Scalar(0.0);
  };
  return (atanDifference(sp) - atanDifference(sm)) / (h * h) + subtendedAngle(b, sm, sp) / (b * (a + b));
}

// The weights of one face for a point x close to its plane (|det| small) whose projection x' is outside the face,
// where the JSW formula loses about eps/|det| (relative) to cancellation. JSW's w_k equals
// 2 int_face phi_k h / R^4 dA (h = n.(p - x), R = |y - x|). With rho = y - x', phi_k = phi_k(x') + g_k . rho:
//   int rho / R^4 = -1/2 sum_i m_i E_i,             E_i = int_{edge i} 1/R^2 ds
//   int h / R^4   = (Gamma - h^2 sum_i d_i G_i) / (2h), d_i = m_i.(p_i - x), Gamma = 0 for x' outside,
//   d_i G_i = sign(d_i) K_i (nearPlaneEdgeTerm with a = |d_i|),
// so w_k = -h (phi_k(x') sum_i sign(d_i) K_i + g_k . sum_i m_i E_i), with no cancellation as h -> 0.
template <typename Scalar>
void nearPlaneWeights(const MeanValueFace& f, const Eigen::Matrix<Scalar, 3, 1>* a, const Scalar& h,
                      const Scalar bary[3], Scalar weights[3]) {
  using std::abs, std::sqrt;
  Scalar edgeSum = 0;
  Eigen::Matrix<Scalar, 3, 1> mE = Eigen::Matrix<Scalar, 3, 1>::Zero();
  for (int i = 0; i < 3; ++i) {
    const Scalar d = a[i].dot(f.m[i]), sm = a[i].dot(f.tau[i]), sp = sm + f.length[i];
    const Scalar K = nearPlaneEdgeTerm(abs(d), h, sm, sp);
    edgeSum += d >= 0 ? K : -K;
    mE += inverseSquareIntegral(sqrt(d * d + h * h), sm, sp) * f.m[i].template cast<Scalar>();
  }
  for (int k = 0; k < 3; ++k) weights[k] = -h * (bary[k] * edgeSum + mE.dot(f.hatGradient[k]) / f.twiceArea);
}

template <typename Scalar>
void meanValue3d(const Cage& cage, const std::vector<MeanValueFace>& faces, const Eigen::Matrix<Scalar, 3, 1>& x,
                 double snap, Scalar* w) {
  using std::abs, std::asin, std::sin;
  using Vector = Eigen::Matrix<Scalar, 3, 1>;
  const int numVertices = cage.numVertices();
  std::vector<Vector> a(numVertices), u(numVertices);
  std::vector<Scalar> d(numVertices);
  for (int i = 0; i < numVertices; ++i) {
    a[i] = cage.vertices.row(i).transpose().template cast<Scalar>() - x;
    d[i] = a[i].norm();
    if (d[i] <= snap) {
      w[i] = 1;
      return;
    }
    u[i] = a[i] / d[i];
  }

  Scalar total = 0;
  for (const MeanValueFace& f : faces) {
    const int* c = f.corner;
    const Vector corner[3] = {a[c[0]], a[c[1]], a[c[2]]};
    const Scalar h = (corner[0] + corner[1] + corner[2]).dot(f.n) / 3;  // signed height of the face plane above x
    Scalar bary[3];  // barycentric coordinates of the projection x' of x on the face plane
    for (int k = 0; k < 3; ++k) bary[k] = corner[(k + 1) % 3].cross(corner[(k + 2) % 3]).dot(f.n) / f.twiceArea;
    const Scalar minBary = smaller(bary[0], smaller(bary[1], bary[2]));

    // x on the face (within rounding): the barycentric coordinates of its projection.
    if (abs(h) <= kOnFace3d * smaller(d[c[0]], smaller(d[c[1]], d[c[2]])) && minBary >= -kOnFace3d) {
      std::fill(w, w + numVertices, Scalar(0.0));
      for (int k = 0; k < 3; ++k) w[c[k]] = bary[k];
      return;
    }

    // det[u0 u1 u2] = twiceArea h / (d0 d1 d2), accurate for x close to the face plane, with the sign of h.
    const Scalar det = f.twiceArea * h / (d[c[0]] * d[c[1]] * d[c[2]]);
    if (det == 0) continue;  // x in the face plane, outside the face: a spherical triangle of zero area

    Scalar weights[3];
    if (minBary < 0 && abs(det) < kNearPlane3d) {
      nearPlaneWeights(f, corner, h, bary, weights);
    } else {
      Scalar theta[3], sinTheta[3];
      for (int k = 0; k < 3; ++k) {
        // theta_k: the arc opposite corner k, between u_{k+1} and u_{k+2}; 2 asin(l/2) is accurate near 0 and pi.
        theta[k] = 2 * asin(smaller(Scalar(1.0), 0.5 * (u[c[(k + 1) % 3]] - u[c[(k + 2) % 3]]).norm()));
        sinTheta[k] = sin(theta[k]);
      }
      const Scalar half = 0.5 * (theta[0] + theta[1] + theta[2]);
      Scalar cosAngle[3];  // cosine of the spherical angle at corner k (half-angle formula of JSW 2005)
      for (int k = 0; k < 3; ++k) {
        const Scalar value = 2 * sin(half) * sin(half - theta[k]) / (sinTheta[(k + 1) % 3] * sinTheta[(k + 2) % 3]) - 1;
        cosAngle[k] = larger(Scalar(-1.0), smaller(value, Scalar(1.0)));
      }
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        // JSW: (theta_k - c_{k+1} theta_{k-1} - c_{k-1} theta_{k+1}) / (d_k sin(theta_{k+1}) s_{k-1}) with
        // s_{k-1} = det / (sin(theta_k) sin(theta_{k+1})), the sine of the spherical angle at corner k-1
        // (sin(theta) >= |det| > 0, so nothing here divides by zero).
        const Scalar numerator = theta[k] - cosAngle[k1] * theta[k2] - cosAngle[k2] * theta[k1];
        weights[k] = numerator * sinTheta[k] / (d[c[k]] * det);
      }
    }
    for (int k = 0; k < 3; ++k) w[c[k]] += weights[k], total += weights[k];
  }
  if (total != 0)
    for (int i = 0; i < numVertices; ++i) w[i] /= total;
}

}  // namespace

namespace {

// The faces meanValue3d integrates over: the non-degenerate ones (see the header).
std::vector<MeanValueFace> meanValueFaces(const Cage& cage) {
  std::vector<MeanValueFace> faces;
  if (cage.dim() != 3) return faces;
  for (int j = 0; j < cage.numFaces(); ++j) {
    MeanValueFace f;
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) f.corner[k] = cage.faces(j, k), p[k] = cage.vertices.row(f.corner[k]);
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    f.twiceArea = normal.norm();
    // A face of zero area covers no solid angle and contributes nothing.
    if (isDegenerateTriangle(p[0], p[1], p[2])) continue;
    f.n = normal / f.twiceArea;
    for (int k = 0; k < 3; ++k) {
      f.length[k] = (p[(k + 1) % 3] - p[k]).norm();
      f.tau[k] = (p[(k + 1) % 3] - p[k]) / f.length[k];
      f.m[k] = f.tau[k].cross(f.n);
      f.hatGradient[k] = f.n.cross(p[(k + 2) % 3] - p[(k + 1) % 3]);
    }
    faces.push_back(f);
  }
  return faces;
}

// The coordinates of point p (#V numbers into w, zeroed by the caller) in a Dim-dimensional cage, as doubles or as
// dual numbers seeded with the unit vectors.
template <typename Scalar, int Dim>
void meanValueOfPoint(const Cage& cage, const std::vector<MeanValueFace>& faces, const Eigen::MatrixXd& points, int p,
                      double snap, Scalar* w) {
  Eigen::Matrix<Scalar, Dim, 1> x;
  for (int a = 0; a < Dim; ++a) {
    if constexpr (std::is_same_v<Scalar, double>)
      x(a) = points(p, a);
    else
      x(a) = Scalar::variable(points(p, a), a);
  }
  if constexpr (Dim == 3)
    meanValue3d<Scalar>(cage, faces, x, snap, w);
  else
    meanValue2d<Scalar>(cage, x, snap, w);
}

template <int Dim>
void meanValueGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads, const ProgressCallback& progress,
                        const GradientRowSink& sink) {
  using Dual = dual::Dual<Dim>;
  const int numVertices = cage.numVertices();
  const double snap = kSnapToVertex * cageDiameter(cage.vertices);
  const std::vector<MeanValueFace> faces = meanValueFaces(cage);
  struct Buffers {
    std::vector<Dual> w;
    std::vector<double> rows;
  };
  forEachPointInBlocks(
      static_cast<int>(points.rows()), cage.numFaces(), threads, progress,
      [&] {
        return Buffers{std::vector<Dual>(numVertices), std::vector<double>(Dim * numVertices)};
      },
      [&](Buffers& b, int p) {
        std::fill(b.w.begin(), b.w.end(), Dual(0.0));
        meanValueOfPoint<Dual, Dim>(cage, faces, points, p, snap, b.w.data());
        const double* rows[Dim];
        for (int a = 0; a < Dim; ++a) {
          for (int i = 0; i < numVertices; ++i) b.rows[a * numVertices + i] = b.w[i].g[a];
          rows[a] = b.rows.data() + a * numVertices;
        }
        sink(p, rows);
      });
}

}  // namespace

RowMatrixXd computeMeanValueCoordinates(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                        const ProgressCallback& progress) {
  assertCageAndPoints(cage, points);
  const int numPoints = static_cast<int>(points.rows());
  RowMatrixXd weights = RowMatrixXd::Zero(numPoints, cage.numVertices());
  const double snap = kSnapToVertex * cageDiameter(cage.vertices);
  const std::vector<MeanValueFace> faces = meanValueFaces(cage);
  forEachPointInBlocks(
      numPoints, cage.numFaces(), threads, progress, [] { return 0; },
      [&](int, int p) {
        if (cage.dim() == 3)
          meanValueOfPoint<double, 3>(cage, faces, points, p, snap, weights.row(p).data());
        else
          meanValueOfPoint<double, 2>(cage, faces, points, p, snap, weights.row(p).data());
      });
  return weights;
}

void integrateMeanValueGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                 const ProgressCallback& progress, const GradientRowSink& sink) {
  assertCageAndPoints(cage, points);
  if (cage.dim() == 3)
    meanValueGradients<3>(cage, points, threads, progress, sink);
  else
    meanValueGradients<2>(cage, points, threads, progress, sink);
}

}  // namespace somicage

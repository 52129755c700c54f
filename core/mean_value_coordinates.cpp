#include "mean_value_coordinates.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "errors.h"
#include "point_blocks.h"

namespace somicage {

namespace {

constexpr double kSnapToVertex = 1e-14;  // times the cage diameter
constexpr double kOnEdge2d = 1e-14;      // |sin alpha| below which a point with cos alpha < 0 is on the edge
constexpr double kOnFace3d = 1e-12;      // |height| / (distance to the nearest corner) below which x is on the face
constexpr double kNearPlane3d = 1e-3;    // |det[u0 u1 u2]| below which x' outside a face uses nearPlaneWeights

// ---------------------------------------------------------------------------------------------------------------
// 2D (Hormann & Floater 2006)
// ---------------------------------------------------------------------------------------------------------------

// Writes the coordinates of x into w (#V, zeroed by the caller).
void meanValue2d(const Cage& cage, const Eigen::Vector2d& x, double snap, double* w) {
  const int numVertices = cage.numVertices();
  std::vector<Eigen::Vector2d> s(numVertices);
  std::vector<double> r(numVertices);
  for (int i = 0; i < numVertices; ++i) {
    s[i] = cage.vertices.row(i).transpose() - x;
    r[i] = s[i].norm();
    if (r[i] <= snap) {
      w[i] = 1;
      return;
    }
  }
  double total = 0;
  for (int j = 0; j < cage.numFaces(); ++j) {
    const int i0 = cage.faces(j, 0), i1 = cage.faces(j, 1);
    const double twiceArea = s[i0].x() * s[i1].y() - s[i0].y() * s[i1].x();  // r0 r1 sin(alpha)
    const double dot = s[i0].dot(s[i1]);                                     // r0 r1 cos(alpha)
    const double rr = r[i0] * r[i1];
    if (std::abs(twiceArea) <= kOnEdge2d * rr && dot < 0) {  // x on the edge: linear interpolation
      std::fill(w, w + numVertices, 0.0);
      w[i0] = r[i1] / (r[i0] + r[i1]);
      w[i1] = r[i0] / (r[i0] + r[i1]);
      return;
    }
    // tan(alpha/2) = sin/(1 + cos) = (1 - cos)/sin: take the form whose denominator cannot cancel.
    const double tanHalf = dot >= 0 ? twiceArea / (rr + dot) : (rr - dot) / twiceArea;
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
double subtendedAngle(double c, double sm, double sp) { return std::atan2(c * (sp - sm), c * c + sm * sp); }

// int_{sm}^{sp} ds / (s^2 + c^2); the limit for c -> 0 when the segment does not contain s = 0.
double inverseSquareIntegral(double c, double sm, double sp) {
  return c > 0 ? subtendedAngle(c, sm, sp) / c : (sp - sm) / (sm * sp);
}

// K = a int_{sm}^{sp} ds / ((s^2 + a^2)(s^2 + b^2)) with b^2 = a^2 + h^2, h != 0. The partial fractions
// (F(a) - (a/b) F(b)) / h^2, F = subtendedAngle, cancel for small h; instead F(a) - F(b) is summed from
// atan(s/a) - atan(s/b) = atan(s (b - a) / (ab + s^2)) and 1 - a/b = h^2 / (b (a + b)), both exact.
double nearPlaneEdgeTerm(double a, double h, double sm, double sp) {
  const double b = std::sqrt(a * a + h * h), delta = h * h / (a + b);
  auto atanDifference = [&](double s) {
    const double denominator = a * b + s * s;
    return denominator > 0 ? std::atan(s * delta / denominator) : 0.0;
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
void nearPlaneWeights(const MeanValueFace& f, const Eigen::Vector3d* a, double h, const double bary[3],
                      double weights[3]) {
  double edgeSum = 0;
  Eigen::Vector3d mE = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const double d = f.m[i].dot(a[i]), sm = f.tau[i].dot(a[i]), sp = sm + f.length[i];
    const double K = nearPlaneEdgeTerm(std::abs(d), h, sm, sp);
    edgeSum += d >= 0 ? K : -K;
    mE += inverseSquareIntegral(std::sqrt(d * d + h * h), sm, sp) * f.m[i];
  }
  for (int k = 0; k < 3; ++k) weights[k] = -h * (bary[k] * edgeSum + f.hatGradient[k].dot(mE) / f.twiceArea);
}

void meanValue3d(const Cage& cage, const std::vector<MeanValueFace>& faces, const Eigen::Vector3d& x, double snap,
                 double* w) {
  const int numVertices = cage.numVertices();
  std::vector<Eigen::Vector3d> a(numVertices), u(numVertices);
  std::vector<double> d(numVertices);
  for (int i = 0; i < numVertices; ++i) {
    a[i] = cage.vertices.row(i).transpose() - x;
    d[i] = a[i].norm();
    if (d[i] <= snap) {
      w[i] = 1;
      return;
    }
    u[i] = a[i] / d[i];
  }

  double total = 0;
  for (const MeanValueFace& f : faces) {
    const int* c = f.corner;
    const Eigen::Vector3d corner[3] = {a[c[0]], a[c[1]], a[c[2]]};
    const double h = f.n.dot(corner[0] + corner[1] + corner[2]) / 3;  // signed height of the face plane above x
    double bary[3];  // barycentric coordinates of the projection x' of x on the face plane
    for (int k = 0; k < 3; ++k) bary[k] = f.n.dot(corner[(k + 1) % 3].cross(corner[(k + 2) % 3])) / f.twiceArea;
    const double minBary = std::min({bary[0], bary[1], bary[2]});

    // x on the face (within rounding): the barycentric coordinates of its projection.
    if (std::abs(h) <= kOnFace3d * std::min({d[c[0]], d[c[1]], d[c[2]]}) && minBary >= -kOnFace3d) {
      std::fill(w, w + numVertices, 0.0);
      for (int k = 0; k < 3; ++k) w[c[k]] = bary[k];
      return;
    }

    // det[u0 u1 u2] = twiceArea h / (d0 d1 d2), accurate for x close to the face plane, with the sign of h.
    const double det = f.twiceArea * h / (d[c[0]] * d[c[1]] * d[c[2]]);
    if (det == 0) continue;  // x in the face plane, outside the face: a spherical triangle of zero area

    double weights[3];
    if (minBary < 0 && std::abs(det) < kNearPlane3d) {
      nearPlaneWeights(f, corner, h, bary, weights);
    } else {
      double theta[3], sinTheta[3];
      for (int k = 0; k < 3; ++k) {
        // theta_k: the arc opposite corner k, between u_{k+1} and u_{k+2}; 2 asin(l/2) is accurate near 0 and pi.
        theta[k] = 2 * std::asin(std::min(1.0, 0.5 * (u[c[(k + 1) % 3]] - u[c[(k + 2) % 3]]).norm()));
        sinTheta[k] = std::sin(theta[k]);
      }
      const double half = 0.5 * (theta[0] + theta[1] + theta[2]);
      double cosAngle[3];  // cosine of the spherical angle at corner k (half-angle formula of JSW 2005)
      for (int k = 0; k < 3; ++k) {
        const double value =
            2 * std::sin(half) * std::sin(half - theta[k]) / (sinTheta[(k + 1) % 3] * sinTheta[(k + 2) % 3]) - 1;
        cosAngle[k] = std::clamp(value, -1.0, 1.0);
      }
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        // JSW: (theta_k - c_{k+1} theta_{k-1} - c_{k-1} theta_{k+1}) / (d_k sin(theta_{k+1}) s_{k-1}) with
        // s_{k-1} = det / (sin(theta_k) sin(theta_{k+1})), the sine of the spherical angle at corner k-1
        // (sin(theta) >= |det| > 0, so nothing here divides by zero).
        const double numerator = theta[k] - cosAngle[k1] * theta[k2] - cosAngle[k2] * theta[k1];
        weights[k] = numerator * sinTheta[k] / (d[c[k]] * det);
      }
    }
    for (int k = 0; k < 3; ++k) w[c[k]] += weights[k], total += weights[k];
  }
  if (total != 0)
    for (int i = 0; i < numVertices; ++i) w[i] /= total;
}

}  // namespace

RowMatrixXd computeMeanValueCoordinates(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                        const ProgressCallback& progress) {
  const int dim = cage.dim();
  assertCageAndPoints(cage, points);

  const int numPoints = static_cast<int>(points.rows());
  RowMatrixXd weights = RowMatrixXd::Zero(numPoints, cage.numVertices());
  const double snap = kSnapToVertex * cageDiameter(cage.vertices);

  std::vector<MeanValueFace> faces;
  if (dim == 3) {
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
  }
  forEachPointInBlocks(
      numPoints, cage.numFaces(), threads, progress, [] { return 0; },
      [&](int, int p) {
        if (dim == 3)
          meanValue3d(cage, faces, points.row(p).transpose(), snap, weights.row(p).data());
        else
          meanValue2d(cage, points.row(p).transpose(), snap, weights.row(p).data());
      });
  return weights;
}

}  // namespace somicage

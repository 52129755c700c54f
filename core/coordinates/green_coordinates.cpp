#include "coordinates/green_coordinates.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>
#include <vector>

#include "base/errors.h"
#include "base/point_blocks.h"
#include "coordinates/coordinate_gradients.h"
#include "deform/boundary_conditions.h"
#include "deform/exterior_points.h"

namespace somicage {

namespace {

// log(max(value, DBL_MIN)): a zero distance (a point exactly on the cage) gives a large finite number, not -inf.
double safeLog(double value) { return std::log(std::max(value, DBL_MIN)); }

// int_{sm}^{sp} ds / sqrt(s^2 + r0sq) for sp > sm, with rm, rp the distances at the two ends.
// Written as log(rp + sp) - log(rm + sm) on the side where no cancellation happens, using
// R + s = r0sq / (R - s) for s < 0.
double inverseDistanceLineIntegral(double sm, double sp, double rm, double rp, double r0sq) {
  if (sm + sp < 0) {  // mirror s -> -s so that the far end is the positive one
    const double t = sm;
    sm = -sp, sp = -t;
    std::swap(rm, rp);
  }
  const double upper = rp + sp;  // sp > 0 here
  const double lower = sm >= 0 ? rm + sm : r0sq / (rm - sm);
  return safeLog(upper) - safeLog(lower);
}

// ---------------------------------------------------------------------------------------------------------------
// 3D: one rest triangle against one point
// ---------------------------------------------------------------------------------------------------------------

struct GreenTriangle {
  Eigen::Vector3d p[3];
  Eigen::Vector3d n;               // unit outward normal
  Eigen::Vector3d tau[3], m[3];    // edge k = p[k] -> p[k+1]: unit direction, outward in-plane normal tau x n
  Eigen::Vector3d hatGradient[3];  // n x (p[k+2] - p[k+1]) = twiceArea * gradient of the hat of corner k
  double twiceArea = 0;
  bool degenerate = false;
};

GreenTriangle makeGreenTriangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  GreenTriangle t;
  t.p[0] = p0, t.p[1] = p1, t.p[2] = p2;
  const Eigen::Vector3d c = (p1 - p0).cross(p2 - p0);
  t.twiceArea = c.norm();
  t.degenerate = isDegenerateTriangle(p0, p1, p2);
  if (t.degenerate) return t;
  t.n = c / t.twiceArea;
  for (int k = 0; k < 3; ++k) {
    t.tau[k] = (t.p[(k + 1) % 3] - t.p[k]).normalized();
    t.m[k] = t.tau[k].cross(t.n);
    t.hatGradient[k] = t.n.cross(t.p[(k + 2) % 3] - t.p[(k + 1) % 3]);
  }
  return t;
}

// D[k] = int phi_k (n.r)/R^3 and S = int 1/R over the triangle, r = y - x, R = |r|.
// With h = n.r (constant on the face), x' the projection of x on the plane and rho = y - x':
//   Omega = int h/R^3                       signed solid angle (van Oosterom & Strackee 1983)
//   int rho/R^3 = -sum_k m_k f_k,           f_k = int_{edge k} 1/R   (divergence theorem on grad 1/R)
//   D_k = phi_k(x') Omega - h grad(phi_k) . sum_k m_k f_k     (phi_k is linear: phi_k(x') + grad phi_k . rho)
//   S   = sum_k d_k f_k - h Omega,          d_k = m_k.(p_k - x)  (divergence of rho/R is 1/R + h^2/R^3)
// Every term stays finite for x in the face plane (h = 0) and near or on an edge or corner.
void integrateGreenTriangle(const GreenTriangle& t, const Eigen::Vector3d& x, double D[3], double& S) {
  Eigen::Vector3d a[3];
  double R[3];
  for (int k = 0; k < 3; ++k) a[k] = t.p[k] - x, R[k] = a[k].norm();
  const double h = t.n.dot(a[0]);

  // det[a0 a1 a2] = twiceArea * h exactly; using it keeps the sign of Omega equal to the sign of h.
  const double denominator = R[0] * R[1] * R[2] + a[0].dot(a[1]) * R[2] + a[0].dot(a[2]) * R[1] + a[1].dot(a[2]) * R[0];
  const double omega = 2 * std::atan2(t.twiceArea * h, denominator);

  Eigen::Vector3d mf = Eigen::Vector3d::Zero();
  S = -h * omega;
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3;
    const double d = t.m[k].dot(a[k]);
    const double sm = t.tau[k].dot(a[k]), sp = t.tau[k].dot(a[k1]);
    const double f = inverseDistanceLineIntegral(sm, sp, R[k], R[k1], d * d + h * h);
    S += d * f;
    mf += f * t.m[k];
  }
  for (int k = 0; k < 3; ++k) {
    // twiceArea * phi_k(x'): the signed area of (x', p_{k+1}, p_{k+2}); the normal components of a cancel.
    const double cornerArea = t.n.dot(a[(k + 1) % 3].cross(a[(k + 2) % 3]));
    D[k] = (cornerArea * omega - h * t.hatGradient[k].dot(mf)) / t.twiceArea;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// 2D: one rest edge against one point
// ---------------------------------------------------------------------------------------------------------------

// D[k] = int phi_k (n.r)/R^2 and S = int ln(1/R) over the edge p0 -> p1 (outward normal n = (e_y, -e_x)/|e|).
// In the edge frame y - x = s tau + h n with s in [s0, s1], s1 = s0 + L:
//   theta = int h/R^2 = atan2(cross(a0, a1), a0.a1)        (the signed angle the edge subtends at x)
//   int s h/R^2 = h ln(R1/R0),  int ln R = s1 ln R1 - s0 ln R0 - L + h theta.
void integrateGreenEdge(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& x, double D[2],
                        double& S) {
  const Eigen::Vector2d e = p1 - p0;
  const double length = e.norm();
  const Eigen::Vector2d tau = e / length, n(tau.y(), -tau.x());
  const Eigen::Vector2d a0 = p0 - x, a1 = p1 - x;
  const double h = n.dot(a0);
  const double s0 = tau.dot(a0), s1 = tau.dot(a1);
  const double theta = std::atan2(a0.x() * a1.y() - a0.y() * a1.x(), a0.dot(a1));
  const double r0sq = a0.squaredNorm(), r1sq = a1.squaredNorm();
  // h ln(R1/R0) -> 0 as h -> 0, also where R0 or R1 is 0 (then h = 0).
  const double hLog = h == 0 ? 0.0 : 0.5 * h * (safeLog(r1sq) - safeLog(r0sq));
  // s ln R -> 0 as R -> 0 (s = 0 there).
  const double s0LogR0 = s0 == 0 ? 0.0 : 0.5 * s0 * safeLog(r0sq), s1LogR1 = s1 == 0 ? 0.0 : 0.5 * s1 * safeLog(r1sq);
  D[0] = (s1 * theta - hLog) / length;
  D[1] = (hLog - s0 * theta) / length;
  S = -(s1LogR1 - s0LogR0 - length + h * theta);
}

}  // namespace

GreenCoordinates computeGreenCoordinates(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                         const ProgressCallback& progress) {
  const int dim = cage.dim();
  assertCageAndPoints(cage, points);

  const int numPoints = static_cast<int>(points.rows());
  GreenCoordinates coords;
  coords.phi = RowMatrixXd::Zero(numPoints, cage.numVertices());
  coords.psi = RowMatrixXd::Zero(numPoints, cage.numFaces());

  std::vector<GreenTriangle> triangles;
  if (dim == 3)
    for (int j = 0; j < cage.numFaces(); ++j)
      triangles.push_back(makeGreenTriangle(cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                                            cage.vertices.row(cage.faces(j, 2))));
  const double scale = 1 / (dim == 3 ? 4 * M_PI : 2 * M_PI);
  forEachPointInBlocks(
      numPoints, cage.numFaces(), threads, progress, [] { return 0; },
      [&](int, int p) {
        double* phi = coords.phi.row(p).data();
        double* psi = coords.psi.row(p).data();
        double D[3], S;
        if (dim == 3) {
          const Eigen::Vector3d x = points.row(p);
          for (int j = 0; j < cage.numFaces(); ++j) {
            if (triangles[j].degenerate) continue;
            integrateGreenTriangle(triangles[j], x, D, S);
            for (int k = 0; k < 3; ++k) phi[cage.faces(j, k)] += scale * D[k];
            psi[j] = scale * S;
          }
        } else {
          const Eigen::Vector2d x = points.row(p);
          for (int j = 0; j < cage.numFaces(); ++j) {
            const Eigen::Vector2d p0 = cage.vertices.row(cage.faces(j, 0)), p1 = cage.vertices.row(cage.faces(j, 1));
            if (isDegenerateFace(cage, j)) continue;
            integrateGreenEdge(p0, p1, x, D, S);
            phi[cage.faces(j, 0)] += scale * D[0];
            phi[cage.faces(j, 1)] += scale * D[1];
            psi[j] = scale * S;
          }
        }
      });
  return coords;
}

Eigen::VectorXd greenFaceScales(const Cage& restCage, const Eigen::MatrixXd& posedVertices) {
  const Eigen::MatrixXd& V = restCage.vertices;
  Eigen::VectorXd scales = Eigen::VectorXd::Zero(restCage.numFaces());
  for (int j = 0; j < restCage.numFaces(); ++j) {
    const int i0 = restCage.faces(j, 0), i1 = restCage.faces(j, 1);
    if (restCage.dim() == 2) {
      const double restLength = (V.row(i1) - V.row(i0)).norm();
      if (restLength > 0) scales(j) = (posedVertices.row(i1) - posedVertices.row(i0)).norm() / restLength;
      continue;
    }
    const int i2 = restCage.faces(j, 2);
    const Eigen::Vector3d u = V.row(i1) - V.row(i0), v = V.row(i2) - V.row(i0);
    const Eigen::Vector3d uu = posedVertices.row(i1) - posedVertices.row(i0);
    const Eigen::Vector3d vv = posedVertices.row(i2) - posedVertices.row(i0);
    const GreenTriangle t = makeGreenTriangle(V.row(i0), V.row(i1), V.row(i2));
    if (t.degenerate) continue;
    const double radicand =
        uu.squaredNorm() * v.squaredNorm() - 2 * uu.dot(vv) * u.dot(v) + vv.squaredNorm() * u.squaredNorm();
    // area = twiceArea / 2, so sqrt(8) * area = sqrt(2) * twiceArea.
    scales(j) = std::sqrt(std::max(radicand, 0.0)) / (std::sqrt(2.0) * t.twiceArea);
  }
  return scales;
}

}  // namespace somicage

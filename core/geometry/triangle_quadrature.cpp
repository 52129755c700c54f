// The paper's quadrature baseline (section 5): 3 quads per triangle, N x N Gauss-Legendre points on each.
#include "geometry/triangle_quadrature.h"

#include <Eigen/Geometry>  // cross
#include <cmath>

#include "base/errors.h"

namespace somicage {

void gaussLegendre01(int count, Eigen::VectorXd& nodes, Eigen::VectorXd& weights) {
  SOMICAGE_ASSERT(count >= 1, "a Gauss-Legendre rule needs at least one point");
  nodes.resize(count);
  weights.resize(count);
  // Roots of P_n by Newton's method from Tricomi's initial guess; the rule is symmetric, so only half is solved.
  for (int i = 0; i < (count + 1) / 2; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (count + 0.5));
    double derivative = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p1 = 1, p2 = 0;  // P_j(z), P_{j-1}(z) by the three-term recurrence
      for (int j = 0; j < count; ++j) {
        const double p3 = p2;
        p2 = p1;
        p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
      }
      derivative = count * (z * p1 - p2) / (z * z - 1);
      const double step = p1 / derivative;
      z -= step;
      if (std::abs(step) <= 1e-15) break;  // quadratic convergence: the next step would be below rounding
    }
    // Recompute P_n'(z) at the converged root for the weight 2 / ((1 - z^2) P_n'^2), halved for [0, 1].
    double p1 = 1, p2 = 0;
    for (int j = 0; j < count; ++j) {
      const double p3 = p2;
      p2 = p1;
      p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
    }
    derivative = count * (z * p1 - p2) / (z * z - 1);
    const double w = 1 / ((1 - z * z) * derivative * derivative);
    // z runs from near +1 downwards; map so that nodes increase on [0, 1].
    nodes(i) = 0.5 * (1 - z);
    nodes(count - 1 - i) = 0.5 * (1 + z);
    weights(i) = weights(count - 1 - i) = w;
  }
  if (count % 2 == 1) nodes(count / 2) = 0.5;  // the middle root is exactly 0
}

void integrateTriangleGauss(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                            const Eigen::Vector3d& x, int pointsPerSide, TriangleIntegrals& out) {
  out.S = 0;
  out.M.setZero();
  for (int k = 0; k < 3; ++k) out.D[k] = 0, out.V[k].setZero(), out.B[k].setZero();
  out.solidAngle = 0;
  const TriangleFrame frame = makeTriangleFrame(p0, p1, p2);  // same normal and degeneracy test as the closed form
  if (frame.degenerate) return;
  const Eigen::Vector3d& n = frame.n;

  // The rule depends only on the count: keep the last one per thread, since every (point, face) pair asks for it.
  thread_local int cachedCount = -1;
  thread_local Eigen::VectorXd nodes, weights;
  if (cachedCount != pointsPerSide) {
    gaussLegendre01(pointsPerSide, nodes, weights);
    cachedCount = pointsPerSide;
  }

  // Work relative to x so that near-field differences are not rounded in absolute coordinates.
  const Eigen::Vector3d P[3] = {p0 - x, p1 - x, p2 - x};
  const double third = 1.0 / 3;
  double Mx[6] = {0, 0, 0, 0, 0, 0};  // upper triangle (xx, xy, xz, yy, yz, zz)
  double Bx[3][6] = {};
  for (int corner = 0; corner < 3; ++corner) {
    // Quad corners in barycentric coordinates: the corner, the midpoint towards the next corner, the centroid,
    // the midpoint towards the previous corner. [0, 1]^2 maps bilinearly onto it.
    double b[4][3] = {};
    b[0][corner] = 1;
    b[1][corner] = 0.5, b[1][(corner + 1) % 3] = 0.5;
    b[2][0] = b[2][1] = b[2][2] = third;
    b[3][corner] = 0.5, b[3][(corner + 2) % 3] = 0.5;
    Eigen::Vector3d c[4];
    for (int i = 0; i < 4; ++i) c[i] = b[i][0] * P[0] + b[i][1] * P[1] + b[i][2] * P[2];
    for (int i = 0; i < pointsPerSide; ++i) {
      const double s = nodes(i);
      for (int j = 0; j < pointsPerSide; ++j) {
        const double t = nodes(j);
        const double w00 = (1 - s) * (1 - t), w10 = s * (1 - t), w11 = s * t, w01 = (1 - s) * t;
        const Eigen::Vector3d r = w00 * c[0] + w10 * c[1] + w11 * c[2] + w01 * c[3];  // y - x
        const Eigen::Vector3d dS = (1 - t) * (c[1] - c[0]) + t * (c[2] - c[3]);
        const Eigen::Vector3d dT = (1 - s) * (c[3] - c[0]) + s * (c[2] - c[1]);
        const double w = weights(i) * weights(j) * dS.cross(dT).norm();
        double phi[3];
        for (int k = 0; k < 3; ++k) phi[k] = w00 * b[0][k] + w10 * b[1][k] + w11 * b[2][k] + w01 * b[3][k];

        const double R2 = r.squaredNorm(), invR = 1 / std::sqrt(R2), invR3 = invR / R2, invR5 = invR3 / R2;
        const double nr = n.dot(r);
        const double rr[6] = {r.x() * r.x(), r.x() * r.y(), r.x() * r.z(), r.y() * r.y(), r.y() * r.z(), r.z() * r.z()};
        out.S += w * invR;
        out.solidAngle -= w * nr * invR3;  // h = n.(x - p0) = -n.r on the face
        for (int a = 0; a < 6; ++a) Mx[a] += w * invR3 * rr[a];
        for (int k = 0; k < 3; ++k) {
          const double wk = w * phi[k];
          out.D[k] += wk * nr * invR3;
          out.V[k] += (wk * invR3) * r;
          for (int a = 0; a < 6; ++a) Bx[k][a] += wk * nr * invR5 * rr[a];
        }
      }
    }
  }
  auto unpack = [](const double s[6], Eigen::Matrix3d& m) {
    m << s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5];
  };
  unpack(Mx, out.M);
  for (int k = 0; k < 3; ++k) unpack(Bx[k], out.B[k]);
}

}  // namespace somicage

// The per-face frame of the closed-form triangle integrals, and the Eigen face of their one implementation,
// triangle_integrals_kernel.h (shared with the CUDA kernels).
#include "geometry/triangle_integrals.h"

#include <Eigen/Geometry>  // cross
#include <algorithm>
#include <cmath>

#include "base/cpu_dispatch.h"
#include "base/simd_math.h"
#include "geometry/cage.h"

namespace somicage {

namespace {

// The frame as plain arrays, for the kernel.
PortableTriangleFrame plainFrame(const TriangleFrame& f) {
  PortableTriangleFrame p;
  for (int i = 0; i < 3; ++i) {
    p.origin[i] = f.origin[i], p.u[i] = f.u[i], p.v[i] = f.v[i], p.n[i] = f.n[i];
    p.ell[i] = f.ell[i];
    p.ellOverTwiceArea[i] = f.ellOverTwiceArea[i];
    for (int j = 0; j < 2; ++j) p.q[i][j] = f.q[i][j], p.tau[i][j] = f.tau[i][j], p.m[i][j] = f.m[i][j];
    for (int j = 0; j < 2; ++j) p.grad[i][j] = f.grad[i][j];
    for (int j = 0; j < 3; ++j)
      p.mm[i][j] = f.mm[i][j], p.tm[i][j] = f.tm[i][j], p.tt[i][j] = f.tt[i][j], p.mDotGrad[i][j] = f.mDotGrad[i][j];
  }
  p.twiceArea = f.twiceArea;
  p.degenerate = f.degenerate ? 1 : 0;
  return p;
}

}  // namespace

TriangleFrame makeTriangleFrame(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  TriangleFrame f;
  f.origin = p0;
  const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
  const Eigen::Vector3d cross = e1.cross(e2);
  const double twiceArea = cross.norm();
  f.degenerate = isDegenerateTriangle(p0, p1, p2);
  if (f.degenerate) {
    f.u.setZero(), f.v.setZero(), f.n.setZero();
    for (int i = 0; i < 3; ++i) {
      f.q[i][0] = f.q[i][1] = 0;
      f.ell[i] = f.ellOverTwiceArea[i] = 0;
      f.tau[i][0] = f.tau[i][1] = f.m[i][0] = f.m[i][1] = f.grad[i][0] = f.grad[i][1] = 0;
      for (int j = 0; j < 3; ++j) f.mm[i][j] = f.tm[i][j] = f.tt[i][j] = f.mDotGrad[i][j] = 0;
    }
    f.kernel = plainFrame(f);
    return f;
  }
  f.twiceArea = twiceArea;
  f.n = cross / twiceArea;
  const double l1 = e1.norm();
  f.u = e1 / l1;
  f.v = f.n.cross(f.u);
  f.q[0][0] = 0, f.q[0][1] = 0;
  f.q[1][0] = l1, f.q[1][1] = 0;
  f.q[2][0] = e2.dot(f.u), f.q[2][1] = e2.dot(f.v);

  for (int e = 0; e < 3; ++e) {
    const int g = (e + 1) % 3;
    const double dx = f.q[g][0] - f.q[e][0], dy = f.q[g][1] - f.q[e][1];
    const double len = std::sqrt(dx * dx + dy * dy);
    f.ell[e] = len;
    f.tau[e][0] = dx / len, f.tau[e][1] = dy / len;
    f.m[e][0] = f.tau[e][1], f.m[e][1] = -f.tau[e][0];  // outward: tau x n
    f.ellOverTwiceArea[e] = len / twiceArea;
    const double* m = f.m[e];
    const double* tau = f.tau[e];
    f.mm[e][0] = m[0] * m[0], f.mm[e][1] = m[0] * m[1], f.mm[e][2] = m[1] * m[1];
    f.tm[e][0] = tau[0] * m[0], f.tm[e][1] = 0.5 * (tau[0] * m[1] + m[0] * tau[1]), f.tm[e][2] = tau[1] * m[1];
    f.tt[e][0] = tau[0] * tau[0], f.tt[e][1] = tau[0] * tau[1], f.tt[e][2] = tau[1] * tau[1];
  }
  // Hat function k is 1 at corner k and 0 on the opposite edge k+1, so its gradient points inward across that edge.
  for (int k = 0; k < 3; ++k) {
    const int e = (k + 1) % 3;
    f.grad[k][0] = -f.m[e][0] * f.ellOverTwiceArea[e];
    f.grad[k][1] = -f.m[e][1] * f.ellOverTwiceArea[e];
  }
  for (int k = 0; k < 3; ++k)
    for (int e = 0; e < 3; ++e) f.mDotGrad[k][e] = f.m[e][0] * f.grad[k][0] + f.m[e][1] * f.grad[k][1];
  f.kernel = plainFrame(f);
  return f;
}

namespace {

void toEigen(const PortableTriangleIntegrals& I, TriangleIntegrals& out) {
  out.S = I.S;
  out.solidAngle = I.solidAngle;
  out.M = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(&I.M[0][0]);
  for (int k = 0; k < 3; ++k) {
    out.D[k] = I.D[k];
    out.V[k] = Eigen::Map<const Eigen::Vector3d>(I.V[k]);
    out.B[k] = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(&I.B[k][0][0]);
  }
}

}  // namespace

// The precompute's kernels, dispatched (cpu_dispatch.h): each call is one point and one face.
SOMICAGE_DISPATCH void integrateTriangle(const TriangleFrame& f, const Eigen::Vector3d& x, TriangleIntegrals& out) {
  PortableTriangleIntegrals I;
  const double point[3] = {x.x(), x.y(), x.z()};
  integrateTrianglePortable(f.kernel, point, I);
  toEigen(I, out);
}

SOMICAGE_DISPATCH void integrateTriangleInteriorLimit(const TriangleFrame& f, const Eigen::Vector3d& onFace,
                                                      TriangleIntegrals& out) {
  PortableTriangleIntegrals I;
  const Eigen::Vector3d rel = onFace - f.origin;
  integrateTriangleLocalPortable(f.kernel, rel.dot(f.u), rel.dot(f.v), -0.0, I);
  toEigen(I, out);
}

SOMICAGE_DISPATCH void integrateTriangle(const TriangleFrame& f, const dual::Dual<3> x[3],
                                         PortableTriangleIntegralsOf<dual::Dual<3>>& out) {
  integrateTrianglePortable(f.kernel, x, out);
}

#if SOMICAGE_SIMD_PACKS
SOMICAGE_DISPATCH void integrateTriangle(const TriangleFrame& f, const dual::Dual<3, simd::Pack> x[3],
                                         PortableTriangleIntegralsOf<dual::Dual<3, simd::Pack>>& out) {
  integrateTrianglePortable(f.kernel, x, out);
}
#endif

}  // namespace somicage

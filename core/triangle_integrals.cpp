// Closed-form triangle integrals: a port of shared docs/closed-form.md section 4 (reference: cf_scalar.py and
// bench.c). Everything is evaluated in the face's local frame [u v n] with origin p0 and rotated to world
// coordinates at the end. The in-plane moments J_p^j = int d^{(x)j} R^-p are reduced to edge integrals by the 2D
// divergence theorem; the stability tricks of section 5 are marked "(5.k)".
#include "triangle_integrals.h"

#include <Eigen/Geometry>  // cross
#include <algorithm>
#include <cmath>
#include <limits>

namespace somicage {

namespace {

// X_world = Q X_local Q^T for a symmetric 3x3 matrix given as its upper triangle (xx, xy, xz, yy, yz, zz), with
// Q = [u v n] given row-major in q.
inline void rotateSymmetric(const double q[3][3], const double l[6], Eigen::Matrix3d& w) {
  double t[3][3];  // t = Q L
  for (int i = 0; i < 3; ++i) {
    t[i][0] = q[i][0] * l[0] + q[i][1] * l[1] + q[i][2] * l[2];
    t[i][1] = q[i][0] * l[1] + q[i][1] * l[3] + q[i][2] * l[4];
    t[i][2] = q[i][0] * l[2] + q[i][1] * l[4] + q[i][2] * l[5];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      const double x = t[i][0] * q[j][0] + t[i][1] * q[j][1] + t[i][2] * q[j][2];
      w(i, j) = x;
      w(j, i) = x;
    }
}

}  // namespace

TriangleFrame makeTriangleFrame(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  TriangleFrame f;
  f.origin = p0;
  const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
  const Eigen::Vector3d cross = e1.cross(e2);
  const double twiceArea = cross.norm();
  const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), (p2 - p1).squaredNorm()});
  // The cross product is only known to about eps |e1| |e2|, so below that the normal is noise: treat as zero area.
  f.degenerate = !(twiceArea > 16 * std::numeric_limits<double>::epsilon() * longest) || !std::isfinite(twiceArea) ||
                 !std::isfinite(longest);
  if (f.degenerate) {
    f.u.setZero(), f.v.setZero(), f.n.setZero();
    for (int i = 0; i < 3; ++i) {
      f.q[i][0] = f.q[i][1] = 0;
      f.ell[i] = f.ellOverTwiceArea[i] = 0;
      f.tau[i][0] = f.tau[i][1] = f.m[i][0] = f.m[i][1] = f.grad[i][0] = f.grad[i][1] = 0;
      for (int j = 0; j < 3; ++j) f.mm[i][j] = f.tm[i][j] = f.tt[i][j] = f.mDotGrad[i][j] = 0;
    }
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
  return f;
}

void integrateTriangle(const TriangleFrame& f, const Eigen::Vector3d& x, TriangleIntegrals& out) {
  if (f.degenerate) {
    out.S = 0;
    out.M.setZero();
    for (int k = 0; k < 3; ++k) out.D[k] = 0, out.V[k].setZero(), out.B[k].setZero();
    out.solidAngle = 0;
    return;
  }

  // ---- Query point in the local frame; differences to the corners taken once (5.4) -----------------------------
  const Eigen::Vector3d rel = x - f.origin;
  const double xu = rel.dot(f.u), xv = rel.dot(f.v), h = rel.dot(f.n), hh = h * h;
  double a[3][2], R[3], invR[3];
  for (int i = 0; i < 3; ++i) {
    a[i][0] = f.q[i][0] - xu;
    a[i][1] = f.q[i][1] - xv;
    R[i] = std::sqrt(a[i][0] * a[i][0] + a[i][1] * a[i][1] + hh);
    invR[i] = 1 / R[i];
  }

  // ---- Edge line integrals along s in [s-, s+] with R^2 = s^2 + rho^2 ------------------------------------------
  // L = int ds/R, E = int ds/R^3, A = int s/R ds, B = int s/R^3 ds, C = int s^2/R^3 ds.
  double t[3], L[3], E[3], A[3], B[3], C[3];
  for (int e = 0; e < 3; ++e) {
    const int g = (e + 1) % 3;
    const double ell = f.ell[e];
    const double te = f.m[e][0] * a[e][0] + f.m[e][1] * a[e][1];
    const double sm = f.tau[e][0] * a[e][0] + f.tau[e][1] * a[e][1], sp = sm + ell;
    const double Rm = R[e], Rp = R[g], rho2 = te * te + hh;
    // R+ - R- without subtracting the two (5.3).
    const double Ae = ell * (sm + sp) / (Rm + Rp);
    double Le, Ee;
    // log((s+ + R+)/(s- + R-)) in log1p form with positive summands only, branched on the sign of s+- (5.3).
    if (sm >= 0) {
      Le = std::log1p((ell + Ae) / (sm + Rm));
      Ee = ell * (sp + sm) * invR[e] * invR[g] / (sp * Rm + sm * Rp);
    } else if (sp <= 0) {
      Le = std::log1p((ell - Ae) / (Rp - sp));
      Ee = ell * (sp + sm) * invR[e] * invR[g] / (sp * Rm + sm * Rp);
    } else {  // the foot of the perpendicular lies inside the edge
      const double U = sp, Vv = -sm, invRho2 = 1 / rho2;
      const double N = U * Vv + U * Rm + Vv * Rp + (U * U * Vv * Vv + rho2 * (U * U + Vv * Vv)) / (Rp * Rm + rho2);
      Le = std::log1p(N * invRho2);
      Ee = (U * invR[g] + Vv * invR[e]) * invRho2;
    }
    t[e] = te, L[e] = Le, E[e] = Ee, A[e] = Ae;
    B[e] = Ae * invR[e] * invR[g];
    C[e] = Le - rho2 * Ee;
  }

  // ---- Signed solid angle W = int h/R^3 as one atan2 (van Oosterom-Strackee, 5.1) -------------------------------
  // The triple product a0.(a1 x a2) is -2A h exactly, so only the denominator is computed from the corners.
  const double d01 = a[0][0] * a[1][0] + a[0][1] * a[1][1] + hh;
  const double d02 = a[0][0] * a[2][0] + a[0][1] * a[2][1] + hh;
  const double d12 = a[1][0] * a[2][0] + a[1][1] * a[2][1] + hh;
  const double W = 2 * std::atan2(f.twiceArea * h, R[0] * R[1] * R[2] + d01 * R[2] + d02 * R[1] + d12 * R[0]);

  // ---- In-plane moments; h is multiplied into every R^-3 and R^-5 moment, nothing divides by h (5.2) -------------
  // 2x2 symmetric matrices are stored as (xx, xy, yy).
  double J1 = -h * W;          // int 1/R
  double J31[2] = {0, 0};      // int d/R^3
  double J32[3] = {0, 0, 0};   // int d d^T/R^3
  double hJ52[3] = {0, 0, 0};  // h int d d^T/R^5
  double h2J51[2] = {0, 0};    // h^2 int d/R^5
  double sumTE = 0;
  double Q[3][3];  // int_e d d^T/R^3 ds
  for (int e = 0; e < 3; ++e) {
    const double tL = t[e] * L[e], htE = h * t[e] * E[e], hB = h * B[e];
    const double t2E = t[e] * t[e] * E[e], twoTB = 2 * t[e] * B[e];
    J1 += tL;
    sumTE += t[e] * E[e];
    J31[0] -= f.m[e][0] * L[e], J31[1] -= f.m[e][1] * L[e];
    h2J51[0] -= f.m[e][0] * E[e], h2J51[1] -= f.m[e][1] * E[e];
    for (int c = 0; c < 3; ++c) {
      J32[c] -= tL * f.mm[e][c] + A[e] * f.tm[e][c];
      hJ52[c] -= htE * f.mm[e][c] + hB * f.tm[e][c];
      Q[e][c] = t2E * f.mm[e][c] + twoTB * f.tm[e][c] + C[e] * f.tt[e][c];
    }
  }
  J32[0] += J1, J32[2] += J1;
  hJ52[0] = (hJ52[0] + W) / 3, hJ52[1] /= 3, hJ52[2] = (hJ52[2] + W) / 3;
  h2J51[0] *= hh / 3, h2J51[1] *= hh / 3;
  const double h3J50 = (W + h * sumTE) / 3;  // h^3 int 1/R^5

  // ---- Outputs: local frame, then rotated to world --------------------------------------------------------------
  const double q[3][3] = {{f.u[0], f.v[0], f.n[0]}, {f.u[1], f.v[1], f.n[1]}, {f.u[2], f.v[2], f.n[2]}};
  out.S = J1;
  out.solidAngle = W;
  {
    const double Ml[6] = {J32[0], J32[1], -h * J31[0], J32[2], -h * J31[1], h * W};
    rotateSymmetric(q, Ml, out.M);
  }
  const double h3 = h / 3;
  for (int k = 0; k < 3; ++k) {
    // phi_k(y) = c + g.d: c is the barycentric coordinate of the projection of x, g the hat gradient.
    const int e = (k + 1) % 3;
    const double c = t[e] * f.ellOverTwiceArea[e];
    const double g0 = f.grad[k][0], g1 = f.grad[k][1];
    const double Dk = -(c * W + h * (g0 * J31[0] + g1 * J31[1]));
    const double V0 = c * J31[0] + J32[0] * g0 + J32[1] * g1;
    const double V1 = c * J31[1] + J32[1] * g0 + J32[2] * g1;
    out.D[k] = Dk;
    for (int i = 0; i < 3; ++i) out.V[k][i] = q[i][0] * V0 + q[i][1] * V1 + q[i][2] * Dk;

    // hK = h int (g.d) d d^T/R^5 (times h): uses J5_3 only contracted with g, through the edge terms Q.
    const double* mg = f.mDotGrad[k];
    const double K00 = h3 * (2 * g0 * J31[0] - (mg[0] * Q[0][0] + mg[1] * Q[1][0] + mg[2] * Q[2][0]));
    const double K01 = h3 * (g0 * J31[1] + J31[0] * g1 - (mg[0] * Q[0][1] + mg[1] * Q[1][1] + mg[2] * Q[2][1]));
    const double K11 = h3 * (2 * g1 * J31[1] - (mg[0] * Q[0][2] + mg[1] * Q[1][2] + mg[2] * Q[2][2]));
    const double w0 = h * (hJ52[0] * g0 + hJ52[1] * g1), w1 = h * (hJ52[1] * g0 + hJ52[2] * g1);
    const double Bl[6] = {-c * hJ52[0] - K00, -c * hJ52[1] - K01, c * h2J51[0] + w0,
                          -c * hJ52[2] - K11, c * h2J51[1] + w1,  -c * h3J50 - h * (g0 * h2J51[0] + g1 * h2J51[1])};
    rotateSymmetric(q, Bl, out.B[k]);
  }
}

}  // namespace somicage

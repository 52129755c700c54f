// The closed-form triangle integrals (shared docs/closed-form.md section 4; reference: cf_scalar.py and bench.c)
// in plain C++ (no Eigen, no heap, no exceptions): the one implementation, which integrateTriangle
// (triangle_integrals.h) wraps on the CPU and the CUDA kernels call on the device (SOMICAGE_HD). Everything is
// evaluated in the face's local frame [u v n] with origin p0 and rotated to world coordinates at the end; the
// in-plane moments J_p^j = int d^{(x)j} R^-p are reduced to edge integrals by the 2D divergence theorem; the
// stability measures of section 5 are marked "(5.k)". Conventions and accuracy: triangle_integrals.h.
#pragma once

#include <math.h>

#include "base/branch_select.h"
#include "base/isa_namespace.h"
#include "base/portable.h"

namespace somicage {

// TriangleFrame (triangle_integrals.h) as plain arrays: makeTriangleFrame fills its `kernel` member.
struct PortableTriangleFrame {
  double origin[3], u[3], v[3], n[3];   // p0 and the orthonormal frame [u v n], u along p1 - p0
  double q[3][2];                       // local 2D corners
  double ell[3], tau[3][2], m[3][2];    // edge lengths, unit directions, outward in-plane normals
  double grad[3][2];                    // in-plane gradients of the hat functions
  double twiceArea;                     // 2A
  int degenerate;                       // 1: a zero-area face, which contributes nothing
  double ellOverTwiceArea[3];           // ell_e / (2A)
  double mm[3][3], tm[3][3], tt[3][3];  // m m^T, sym(tau m^T), tau tau^T per edge as (xx, xy, yy)
  double mDotGrad[3][3];                // [k][e] = m_e . grad_k
};
SOMICAGE_ISA_BEGIN  // the data above is one type for every copy; the functions below are per copy

// TriangleIntegrals with plain arrays; matrices are row-major [i][j], V and B indexed by the corner k first.
// Scalar is double, or a dual number (dual_number.h) when the gradients with respect to x are wanted as well.
template <typename Scalar>
struct PortableTriangleIntegralsOf {
  Scalar S;           // int 1/R
  Scalar M[3][3];     // int r r^T / R^3
  Scalar D[3];        // int phi_k (n.r) / R^3
  Scalar V[3][3];     // int phi_k r / R^3
  Scalar B[3][3][3];  // int phi_k (n.r) r r^T / R^5
  Scalar solidAngle;  // signed solid angle, -2pi just inside the face
};
using PortableTriangleIntegrals = PortableTriangleIntegralsOf<double>;

namespace portable_detail {

// X_world = Q X_local Q^T for a symmetric 3x3 matrix given as (xx, xy, xz, yy, yz, zz), Q = [u v n] row-major.
template <typename Scalar>
SOMICAGE_HD inline void rotateSymmetric(const double q[3][3], const Scalar l[6], Scalar w[3][3]) {
  Scalar t[3][3];  // t = Q L
  for (int i = 0; i < 3; ++i) {
    t[i][0] = q[i][0] * l[0] + q[i][1] * l[1] + q[i][2] * l[2];
    t[i][1] = q[i][0] * l[1] + q[i][1] * l[3] + q[i][2] * l[4];
    t[i][2] = q[i][0] * l[2] + q[i][1] * l[4] + q[i][2] * l[5];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      const Scalar x = t[i][0] * q[j][0] + t[i][1] * q[j][1] + t[i][2] * q[j][2];
      w[i][j] = x;
      w[j][i] = x;
    }
}

}  // namespace portable_detail

// What the outputs of integrateTriangleLocalPortable are made of: the differences to the corners, the edge line
// integrals and the in-plane moments (closed-form.md section 4). The closed-form gradients
// (triangle_gradients_kernel.h) are made of the same quantities.
template <typename Scalar>
struct PortableTriangleMoments {
  Scalar a[3][2], R[3], invR[3];  // corner i minus the projection of x (local 2D), |y_i - x|, 1 / |y_i - x|
  // Edge e from corner e to e + 1 along s in [s-, s+] with R^2 = s^2 + rho^2: t = m_e . a_e, s- = tau_e . a_e,
  // L = int ds/R, E = int ds/R^3, A = int s/R ds, B = int s/R^3 ds, C = int s^2/R^3 ds.
  Scalar t[3], sm[3], rho2[3], L[3], E[3], A[3], B[3], C[3];
  Scalar W;                 // signed solid angle int h/R^3
  Scalar J1;                // int 1/R
  Scalar J31[2];            // int d/R^3
  Scalar J32[3];            // int d d^T/R^3 as (xx, xy, yy)
  Scalar hJ52[3];           // h int d d^T/R^5
  Scalar h2J51[2];          // h^2 int d/R^5
  Scalar h3J50;             // h^3 int 1/R^5
  Scalar Q[3][3];           // int_e d d^T/R^3 ds per edge
};

// The moments for the point with local coordinates (xu, xv, h) in the face's frame [u v n] about p0 (a
// non-degenerate face).
template <typename Scalar>
SOMICAGE_HD inline void triangleMomentsPortable(const PortableTriangleFrame& f, const Scalar& xu, const Scalar& xv,
                                                const Scalar& h, PortableTriangleMoments<Scalar>& mo) {
  // ---- Differences to the corners in the local frame, taken once (5.4) -------------------------------------------
  const Scalar hh = h * h;
  Scalar(&a)[3][2] = mo.a;
  Scalar(&R)[3] = mo.R;
  Scalar(&invR)[3] = mo.invR;
  for (int i = 0; i < 3; ++i) {
    a[i][0] = f.q[i][0] - xu;
    a[i][1] = f.q[i][1] - xv;
    R[i] = sqrt(a[i][0] * a[i][0] + a[i][1] * a[i][1] + hh);
    invR[i] = 1 / R[i];
  }

  // ---- Edge line integrals along s in [s-, s+] with R^2 = s^2 + rho^2 ------------------------------------------
  Scalar(&t)[3] = mo.t;
  Scalar(&L)[3] = mo.L;
  Scalar(&E)[3] = mo.E;
  Scalar(&A)[3] = mo.A;
  Scalar(&B)[3] = mo.B;
  Scalar(&C)[3] = mo.C;
  for (int e = 0; e < 3; ++e) {
    const int g = (e + 1) % 3;
    const double ell = f.ell[e];
    const Scalar te = f.m[e][0] * a[e][0] + f.m[e][1] * a[e][1];
    const Scalar sm = f.tau[e][0] * a[e][0] + f.tau[e][1] * a[e][1], sp = sm + ell;
    const Scalar Rm = R[e], Rp = R[g], rho2 = te * te + hh;
    const Scalar Ae = ell * (sm + sp) / (Rm + Rp);  // R+ - R- without subtracting the two (5.3)
    // log((s+ + R+)/(s- + R-)) in log1p form with positive summands only, branched on the sign of s+- (5.3). Each
    // branch gives the argument of log1p and E (branch_select.h: packs take the branches lane by lane).
    using Pair = ScalarPair<Scalar>;
    const auto endsE = [&] { return ell * (sp + sm) * invR[e] * invR[g] / (sp * Rm + sm * Rp); };
    const Pair logArgAndE = branchSelect(
        sm >= 0, [&] { return Pair{(ell + Ae) / (sm + Rm), endsE()}; },
        [&] {
          return branchSelect(
              sp <= 0, [&] { return Pair{(ell - Ae) / (Rp - sp), endsE()}; },
              [&] {  // the foot of the perpendicular lies inside the edge
                const Scalar U = sp, Vv = -sm, invRho2 = 1 / rho2;
                const Scalar N =
                    U * Vv + U * Rm + Vv * Rp + (U * U * Vv * Vv + rho2 * (U * U + Vv * Vv)) / (Rp * Rm + rho2);
                return Pair{N * invRho2, (U * invR[g] + Vv * invR[e]) * invRho2};
              });
        });
    const Scalar Le = log1p(logArgAndE.first), Ee = logArgAndE.second;
    t[e] = te, L[e] = Le, E[e] = Ee, A[e] = Ae;
    mo.sm[e] = sm, mo.rho2[e] = rho2;
    B[e] = Ae * invR[e] * invR[g];
    C[e] = Le - rho2 * Ee;
  }

  // ---- Signed solid angle W = int h/R^3 as one atan2 (van Oosterom-Strackee, 5.1) -------------------------------
  const Scalar d01 = a[0][0] * a[1][0] + a[0][1] * a[1][1] + hh;
  const Scalar d02 = a[0][0] * a[2][0] + a[0][1] * a[2][1] + hh;
  const Scalar d12 = a[1][0] * a[2][0] + a[1][1] * a[2][1] + hh;
  const Scalar W = 2 * atan2(f.twiceArea * h, R[0] * R[1] * R[2] + d01 * R[2] + d02 * R[1] + d12 * R[0]);
  mo.W = W;

  // ---- In-plane moments; h is multiplied into every R^-3 and R^-5 moment, nothing divides by h (5.2) -------------
  Scalar J1 = -h * W;          // int 1/R
  Scalar J31[2] = {0, 0};      // int d/R^3
  Scalar J32[3] = {0, 0, 0};   // int d d^T/R^3
  Scalar hJ52[3] = {0, 0, 0};  // h int d d^T/R^5
  Scalar h2J51[2] = {0, 0};    // h^2 int d/R^5
  Scalar sumTE = 0;
  Scalar(&Q)[3][3] = mo.Q;  // int_e d d^T/R^3 ds
  for (int e = 0; e < 3; ++e) {
    const Scalar tL = t[e] * L[e], htE = h * t[e] * E[e], hB = h * B[e];
    const Scalar t2E = t[e] * t[e] * E[e], twoTB = 2 * t[e] * B[e];
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
  mo.h3J50 = (W + h * sumTE) / 3;  // h^3 int 1/R^5
  mo.J1 = J1;
  for (int c = 0; c < 3; ++c) mo.J32[c] = J32[c], mo.hJ52[c] = hJ52[c];
  for (int c = 0; c < 2; ++c) mo.J31[c] = J31[c], mo.h2J51[c] = h2J51[c];
}

// integrateTrianglePortable for the point with local coordinates (xu, xv, h) in the face's frame [u v n] about p0.
// h = -0.0 with (xu, xv) strictly inside the face is the limit from the inside of the cage (W = -2pi): every other
// term is continuous there and every h-weighted one vanishes (bem_layer_integrals.h relies on this).
template <typename Scalar>
SOMICAGE_HD inline void integrateTriangleLocalPortable(const PortableTriangleFrame& f, const Scalar& xu,
                                                       const Scalar& xv, const Scalar& h,
                                                       PortableTriangleIntegralsOf<Scalar>& out) {
  if (f.degenerate) {
    out.S = 0, out.solidAngle = 0;
    for (int i = 0; i < 3; ++i) {
      out.D[i] = 0;
      for (int j = 0; j < 3; ++j) {
        out.M[i][j] = out.V[i][j] = 0;
        for (int k = 0; k < 3; ++k) out.B[i][j][k] = 0;
      }
    }
    return;
  }
  PortableTriangleMoments<Scalar> mo;
  triangleMomentsPortable(f, xu, xv, h, mo);
  const Scalar(&t)[3] = mo.t;
  const Scalar W = mo.W, J1 = mo.J1, h3J50 = mo.h3J50;
  const Scalar(&J31)[2] = mo.J31;
  const Scalar(&J32)[3] = mo.J32;
  const Scalar(&hJ52)[3] = mo.hJ52;
  const Scalar(&h2J51)[2] = mo.h2J51;
  const Scalar(&Q)[3][3] = mo.Q;

  // ---- Outputs: local frame, then rotated to world --------------------------------------------------------------
  const double q[3][3] = {{f.u[0], f.v[0], f.n[0]}, {f.u[1], f.v[1], f.n[1]}, {f.u[2], f.v[2], f.n[2]}};
  out.S = J1;
  out.solidAngle = W;
  {
    const Scalar Ml[6] = {J32[0], J32[1], -h * J31[0], J32[2], -h * J31[1], h * W};
    portable_detail::rotateSymmetric(q, Ml, out.M);
  }
  const Scalar h3 = h / 3;
  for (int k = 0; k < 3; ++k) {
    // phi_k(y) = c + g.d: c is the barycentric coordinate of the projection of x, g the hat gradient.
    const int e = (k + 1) % 3;
    const Scalar c = t[e] * f.ellOverTwiceArea[e];
    const double g0 = f.grad[k][0], g1 = f.grad[k][1];
    const Scalar Dk = -(c * W + h * (g0 * J31[0] + g1 * J31[1]));
    const Scalar V0 = c * J31[0] + J32[0] * g0 + J32[1] * g1;
    const Scalar V1 = c * J31[1] + J32[1] * g0 + J32[2] * g1;
    out.D[k] = Dk;
    for (int i = 0; i < 3; ++i) out.V[k][i] = q[i][0] * V0 + q[i][1] * V1 + q[i][2] * Dk;

    // hK = h int (g.d) d d^T/R^5 (times h): uses J5_3 only contracted with g, through the edge terms Q.
    const double* mg = f.mDotGrad[k];
    const Scalar K00 = h3 * (2 * g0 * J31[0] - (mg[0] * Q[0][0] + mg[1] * Q[1][0] + mg[2] * Q[2][0]));
    const Scalar K01 = h3 * (g0 * J31[1] + J31[0] * g1 - (mg[0] * Q[0][1] + mg[1] * Q[1][1] + mg[2] * Q[2][1]));
    const Scalar K11 = h3 * (2 * g1 * J31[1] - (mg[0] * Q[0][2] + mg[1] * Q[1][2] + mg[2] * Q[2][2]));
    const Scalar w0 = h * (hJ52[0] * g0 + hJ52[1] * g1), w1 = h * (hJ52[1] * g0 + hJ52[2] * g1);
    const Scalar Bl[6] = {-c * hJ52[0] - K00, -c * hJ52[1] - K01, c * h2J51[0] + w0,
                          -c * hJ52[2] - K11, c * h2J51[1] + w1,  -c * h3J50 - h * (g0 * h2J51[0] + g1 * h2J51[1])};
    portable_detail::rotateSymmetric(q, Bl, out.B[k]);
  }
}

// integrateTriangle (core/geometry/triangle_integrals.h) for the point x; a degenerate frame gives all zeros. With dual
// numbers for x (seeded with the unit vectors) every output carries its exact gradient with respect to x.
template <typename Scalar>
SOMICAGE_HD inline void integrateTrianglePortable(const PortableTriangleFrame& f, const Scalar x[3],
                                                  PortableTriangleIntegralsOf<Scalar>& out) {
  const Scalar rel[3] = {x[0] - f.origin[0], x[1] - f.origin[1], x[2] - f.origin[2]};
  const Scalar xu = rel[0] * f.u[0] + rel[1] * f.u[1] + rel[2] * f.u[2];
  const Scalar xv = rel[0] * f.v[0] + rel[1] * f.v[1] + rel[2] * f.v[2];
  const Scalar h = rel[0] * f.n[0] + rel[1] * f.n[1] + rel[2] * f.n[2];
  integrateTriangleLocalPortable(f, xu, xv, h, out);
}

SOMICAGE_ISA_END
}  // namespace somicage

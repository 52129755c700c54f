// The gradients with respect to the point x of the closed-form triangle integrals (triangle_integrals_kernel.h) in
// closed form: no dual numbers. Derivation (docs/closed-form-gradients.md has it in full):
//
// - In the face's frame [u v n] (x at in-plane position xi, height h), every output is an integral over the face of
//   phi(y) g(y - xi, h) with phi = 1 or a hat function phi_k (affine, in-plane gradient gamma_k). Moving x in the
//   plane moves the kernel: by the 2D divergence theorem
//       d/dxi_a int phi g = -sum_e m_e,a int_e phi g ds + gamma_a int g,                                   (G1)
//   an edge integral of the kernel and the same area integral. Along an edge phi_k runs linearly from 1 to 0, so the
//   edge integrals are the moments int s^j/R^3 (E, B, C of the value kernel) and int s^j/R^5 (F0..F3, below).
// - V_k = grad F_k and D_k = n . V_k with F_k = int phi_k/R, the single layer of the hat, so grad V_k = H_k, the
//   Hessian of F_k: its in-plane rows by (G1) from V_k and D_k, the nn entry from trace H_k = 0 (F_k is harmonic
//   off the face): no derivative in h is taken.
// - B_k (Wm_k of closed-form.md) = (D_k I - h H_k) / 3, so d_c B_k,ab = (delta_ab H_k,cn - delta_cn H_k,ab -
//   h T_k,cab) / 3 with T_k the third derivatives of F_k (symmetric and trace-free): its in-plane entries by (G1)
//   applied to H_k, the rest from the traces.
// - S: grad S = int r/R^3 = U, local (J31, -W). M = int r r^T/R^3: d_c M_ab = -delta_ac U_b - delta_bc U_a +
//   3 int r_a r_b r_c/R^5, whose entries are the value kernel's moments (J53 through Q and J31, h J52, h^2 J51,
//   h^3 J50).
// Every R^-5 edge moment is written with positive summands only (F0, F3) or as a product of stable factors, like E
// (closed-form.md 5.3), and h multiplies every R^-5 term, as in the value kernel (5.2): nothing divides by h.
#pragma once

#include "base/isa_namespace.h"
#include "geometry/triangle_integrals_kernel.h"

namespace somicage {
SOMICAGE_ISA_BEGIN

namespace portable_detail {

constexpr double kThird = 1.0 / 3;  // a product rather than a division by 3 (a few times faster in packs)

// w = Q l for a vector, Q = [u v n] row-major.
template <typename Scalar>
SOMICAGE_HD inline void rotateVector(const double q[3][3], const Scalar l[3], Scalar w[3]) {
  for (int i = 0; i < 3; ++i) w[i] = q[i][0] * l[0] + q[i][1] * l[1] + q[i][2] * l[2];
}

// W_ijk = sum Q_ia Q_jb Q_kc L_abc for a symmetric 3-tensor given by its 10 entries in the order of
// kSymmetric3 (aaa with a <= b <= c: uuu, uuv, uun, uvv, uvn, unn, vvv, vvn, vnn, nnn); W returned as all 27.
constexpr int kSymmetric3[3][3][3] = {{{0, 1, 2}, {1, 3, 4}, {2, 4, 5}},
                                      {{1, 3, 4}, {3, 6, 7}, {4, 7, 8}},
                                      {{2, 4, 5}, {4, 7, 8}, {5, 8, 9}}};
constexpr int kSymmetric2[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};  // (xx, xy, xz, yy, yz, zz)

template <typename Scalar>
SOMICAGE_HD inline void rotateSymmetric3(const double q[3][3], const Scalar l[10], Scalar w[3][3][3]) {
  Scalar a[6][3];  // a[ab][k] = sum_c Q_kc L_abc, symmetric in ab
  for (int p = 0; p < 6; ++p) {
    const int i = p < 3 ? 0 : (p < 5 ? 1 : 2), j = p < 3 ? p : (p < 5 ? p - 2 : 2);
    for (int k = 0; k < 3; ++k)
      a[p][k] = q[k][0] * l[kSymmetric3[i][j][0]] + q[k][1] * l[kSymmetric3[i][j][1]] +
                q[k][2] * l[kSymmetric3[i][j][2]];
  }
  Scalar b[3][6];  // b[a][jk] = sum_b Q_jb a[ab][k], symmetric in jk
  for (int i = 0; i < 3; ++i)
    for (int p = 0; p < 6; ++p) {
      const int j = p < 3 ? 0 : (p < 5 ? 1 : 2), k = p < 3 ? p : (p < 5 ? p - 2 : 2);
      b[i][p] = q[j][0] * a[kSymmetric2[i][0]][k] + q[j][1] * a[kSymmetric2[i][1]][k] +
                q[j][2] * a[kSymmetric2[i][2]][k];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      for (int k = j; k < 3; ++k) {
        const int p = kSymmetric2[j][k];
        const Scalar x = q[i][0] * b[0][p] + q[i][1] * b[1][p] + q[i][2] * b[2][p];
        w[i][j][k] = w[i][k][j] = w[j][i][k] = w[j][k][i] = w[k][i][j] = w[k][j][i] = x;
      }
}

}  // namespace portable_detail

// dx[i] = d/dx_i of every output of integrateTrianglePortable(f, x) (world coordinates), except solidAngle (0).
template <typename Scalar>
SOMICAGE_HD inline void integrateTriangleGradientsPortable(const PortableTriangleFrame& f, const Scalar x[3],
                                                           PortableTriangleIntegralsOf<Scalar> (&dx)[3]) {
  using portable_detail::kThird;
  if (f.degenerate) {  // all zeros, as the values are
    for (auto& d : dx) integrateTriangleLocalPortable(f, Scalar(0), Scalar(0), Scalar(0), d);
    return;
  }
  for (auto& d : dx) d.solidAngle = 0;
  const Scalar rel[3] = {x[0] - f.origin[0], x[1] - f.origin[1], x[2] - f.origin[2]};
  const Scalar xu = rel[0] * f.u[0] + rel[1] * f.u[1] + rel[2] * f.u[2];
  const Scalar xv = rel[0] * f.v[0] + rel[1] * f.v[1] + rel[2] * f.v[2];
  const Scalar h = rel[0] * f.n[0] + rel[1] * f.n[1] + rel[2] * f.n[2];
  PortableTriangleMoments<Scalar> mo;
  triangleMomentsPortable(f, xu, xv, h, mo);
  const Scalar W = mo.W, hh = h * h;

  // Local second derivatives H_k of F_k (xx, xy, xz, yy, yz, zz in u, v, n) and h times the third ones T_k (the
  // in-plane entries uuu, uuv, uvv, vvv, uun, uvn, vvn; the others follow from the traces).
  Scalar H[3][6], T[3][7];
  for (int k = 0; k < 3; ++k) {
    const double g0 = f.grad[k][0], g1 = f.grad[k][1];
    H[k][0] = g0 * mo.J31[0], H[k][1] = g0 * mo.J31[1], H[k][3] = g1 * mo.J31[1];  // gamma_a J31_b of (G1)
    H[k][2] = -g0 * W, H[k][4] = -g1 * W;                                          // gamma_a int (-h/R^3)
    for (int c = 0; c < 7; ++c) T[k][c] = 0;
  }
  Scalar H0[4] = {0, 0, 0, 0};  // H of the constant density (uu, vv, un, vn): the gamma terms of T_k
  for (int e = 0; e < 3; ++e) {
    const int g = (e + 1) % 3;
    const double ell = f.ell[e], m0 = f.m[e][0], m1 = f.m[e][1], t0 = f.tau[e][0], t1 = f.tau[e][1];
    const Scalar s1 = mo.sm[e], s2 = s1 + ell, te = mo.t[e], rho2 = mo.rho2[e];
    const Scalar iR1 = mo.invR[e], iR2 = mo.invR[g], E = mo.E[e], B = mo.B[e], C = mo.C[e];
    const Scalar sig1 = s1 * iR1, sig2 = s2 * iR2, iR12 = iR1 * iR2, R12 = mo.R[e] * mo.R[g];
    // F_j = int s^j/R^5 ds. With s = rho tan(theta): F0 = (E/3)(1/R1^2 + 1/R2^2 + (1 - sig1 sig2)/rho^2) and
    // 1 - sig1 sig2 = rho^2 (s1^2 + s2^2 + rho^2) / (R1 R2 (R1 R2 + s1 s2)) when s1 s2 >= 0 (positive summands; the
    // edge's extension, rho -> 0, included), else directly (the foot inside the edge: 1 + |sig1 sig2|).
    using Pair = ScalarPair<Scalar>;
    const auto sameSign = [&] { return Pair{(s1 * s1 + s2 * s2 + rho2) * iR12 / (R12 + s1 * s2), Scalar(0)}; };
    const Scalar Y = branchSelect(
                         s1 >= 0, sameSign,
                         [&] {
                           return branchSelect(s2 <= 0, sameSign,
                                               [&] { return Pair{(1 - sig1 * sig2) / rho2, Scalar(0)}; });
                         })
                         .first;
    const Scalar E3 = E * kThird, B3 = B * kThird;
    const Scalar F0 = E3 * (iR1 * iR1 + iR2 * iR2 + Y);
    const Scalar F1 = B3 * (iR1 * iR1 + iR12 + iR2 * iR2);  // (1/R1^3 - 1/R2^3)/3 with B = 1/R1 - 1/R2
    const Scalar F2 = E3 * (sig1 * sig1 + sig1 * sig2 + sig2 * sig2);
    // F3 = B - rho^2 F1 = (B/3)(sig1^2 + sig2^2 + 1 - rho^2/(R1 R2)), the last with positive summands.
    const Scalar F3 =
        B3 * (sig1 * sig1 + sig2 * sig2 + (s1 * s1 * s2 * s2 + rho2 * (s1 * s1 + s2 * s2)) * iR12 / (R12 + rho2));

    // The constant density: phi = 1.
    H0[0] -= m0 * (te * m0 * E + t0 * B), H0[1] -= m1 * (te * m1 * E + t1 * B);
    H0[2] += h * m0 * E, H0[3] += h * m1 * E;

    // The two hats that live on this edge: phi_e = (s2 - s)/ell, phi_g = (s - s1)/ell, as phi = p + q s.
    const double invEll = 1 / ell;
    for (int side = 0; side < 2; ++side) {
      const int k = side == 0 ? e : g;
      const Scalar p = side == 0 ? s2 * invEll : -s1 * invEll;
      const double q = side == 0 ? -invEll : invEll;
      const Scalar e0 = p * E + q * B, e1 = p * B + q * C;                          // int phi s^j/R^3
      const Scalar f0 = p * F0 + q * F1, f1 = p * F1 + q * F2, f2 = p * F2 + q * F3;  // int phi s^j/R^5
      // H_k by (G1): int_e phi d/R^3 with d = t m + s tau, and int_e phi (-h)/R^3.
      const Scalar P0 = te * m0 * e0 + t0 * e1, P1 = te * m1 * e0 + t1 * e1;
      H[k][0] -= m0 * P0, H[k][1] -= m0 * P1, H[k][3] -= m1 * P1;
      H[k][2] += h * m0 * e0, H[k][4] += h * m1 * e0;
      // h T_k by (G1) on H_k: h int_e phi K_ab with K = 3 r r^T/R^5 - I/R^3, r = (d, -h).
      const Scalar t2f0 = te * te * f0, twoTf1 = 2 * te * f1;
      const Scalar Xuu = 3 * h * (t2f0 * f.mm[e][0] + twoTf1 * f.tm[e][0] + f2 * f.tt[e][0]) - h * e0;
      const Scalar Xvv = 3 * h * (t2f0 * f.mm[e][2] + twoTf1 * f.tm[e][2] + f2 * f.tt[e][2]) - h * e0;
      const Scalar tf0 = te * f0, h2x3 = 3 * hh;
      const Scalar Yu = -h2x3 * (tf0 * m0 + f1 * t0), Yv = -h2x3 * (tf0 * m1 + f1 * t1);
      T[k][0] -= m0 * Xuu, T[k][1] -= m1 * Xuu, T[k][2] -= m0 * Xvv, T[k][3] -= m1 * Xvv;
      T[k][4] -= m0 * Yu, T[k][5] -= m0 * Yv, T[k][6] -= m1 * Yv;
    }
  }

  // ---- To world coordinates: every derivative direction and tensor index rotated by Q = [u v n] ------------------
  const double q[3][3] = {{f.u[0], f.v[0], f.n[0]}, {f.u[1], f.v[1], f.n[1]}, {f.u[2], f.v[2], f.n[2]}};
  const double* n = f.n;
  for (int k = 0; k < 3; ++k) {
    const double g0 = f.grad[k][0], g1 = f.grad[k][1];
    Scalar* Tk = T[k];
    Tk[0] += g0 * h * H0[0], Tk[1] += g1 * h * H0[0], Tk[2] += g0 * h * H0[1], Tk[3] += g1 * h * H0[1];
    Tk[4] += g0 * h * H0[2], Tk[5] += g0 * h * H0[3], Tk[6] += g1 * h * H0[3];
    H[k][5] = -(H[k][0] + H[k][3]);
    // T's 10 entries (kSymmetric3's order) from the 7 and the traces T_ann = -(T_auu + T_avv).
    const Scalar unn = -(Tk[0] + Tk[2]), vnn = -(Tk[1] + Tk[3]), nnn = -(Tk[4] + Tk[6]);
    const Scalar Tl[10] = {Tk[0], Tk[1], Tk[4], Tk[2], Tk[5], unn, Tk[3], Tk[6], vnn, nnn};
    Scalar Hw[3][3], Tw[3][3][3], DD[3];
    portable_detail::rotateSymmetric(q, H[k], Hw);
    portable_detail::rotateSymmetric3(q, Tl, Tw);
    const Scalar Hn[3] = {H[k][2], H[k][4], H[k][5]};  // grad D_k (local)
    portable_detail::rotateVector(q, Hn, DD);
    for (int i = 0; i < 3; ++i) {
      PortableTriangleIntegralsOf<Scalar>& d = dx[i];
      d.D[k] = DD[i];
      for (int a = 0; a < 3; ++a) {
        d.V[k][a] = Hw[i][a];
        for (int b = a; b < 3; ++b)
          d.B[k][a][b] = d.B[k][b][a] = ((a == b ? DD[i] : Scalar(0)) - n[i] * Hw[a][b] - Tw[i][a][b]) * kThird;
      }
    }
  }

  // S and M: U = grad S = int r/R^3 (local (J31, -W)) and the third moment int r r r/R^5.
  const Scalar Ul[3] = {mo.J31[0], mo.J31[1], -W};
  Scalar Uw[3], Mw[3][3][3];
  portable_detail::rotateVector(q, Ul, Uw);
  {
    Scalar sumQ[4] = {0, 0, 0, 0};  // sum_e m_e,u Q_e,uu; m_e,v Q_e,uu; m_e,u Q_e,vv; m_e,v Q_e,vv
    for (int e = 0; e < 3; ++e) {
      sumQ[0] += f.m[e][0] * mo.Q[e][0], sumQ[1] += f.m[e][1] * mo.Q[e][0];
      sumQ[2] += f.m[e][0] * mo.Q[e][2], sumQ[3] += f.m[e][1] * mo.Q[e][2];
    }
    // J53_abc = (delta_ac J31_b + delta_bc J31_a - sum_e m_e,c Q_e,ab) / 3 (the divergence of d_a d_b/R^3).
    const Scalar Ml[10] = {(2 * mo.J31[0] - sumQ[0]) * kThird, -sumQ[1] * kThird, -mo.hJ52[0], -sumQ[2] * kThird,
                           -mo.hJ52[1], mo.h2J51[0], (2 * mo.J31[1] - sumQ[3]) * kThird, -mo.hJ52[2],
                           mo.h2J51[1], -mo.h3J50};
    portable_detail::rotateSymmetric3(q, Ml, Mw);
  }
  for (int i = 0; i < 3; ++i) {
    PortableTriangleIntegralsOf<Scalar>& d = dx[i];
    d.S = Uw[i];
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        Scalar m = 3 * Mw[i][a][b];
        if (i == a) m = m - Uw[b];
        if (i == b) m = m - Uw[a];
        d.M[a][b] = d.M[b][a] = m;
      }
  }
}

SOMICAGE_ISA_END
}  // namespace somicage

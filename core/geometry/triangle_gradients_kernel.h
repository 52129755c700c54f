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

// What the gradients need of a face beyond its frame, once per cage: its derivative tensors rotated to world
// coordinates (W_ij.. = sum Q_ia Q_jb .. L_ab.., Q = [u v n]) as tables on the tensors' distinct entries, so that a
// rotation costs 10 N multiply-adds for N local entries (a trace-free 3-tensor: 49 for seven world entries, the
// other three from its traces) instead of about 140 for the three contractions with Q; the gradients rotate four
// 3-tensors and three matrices per face. Plain data, made by
// the caller and shared by every instruction set's copy of the kernels.
struct PortableGradientFrame {
  double sym3[10][10];      // world entry (kSymmetric3's order) of a symmetric 3-tensor from its 10 local ones
  double traceFree3[7][7];  // of a trace-free one (its world entries but xzz, yzz, zzz) from uuu, uuv, uvv, vvv,
                            // uun, uvn, vvn, times -1/3 (B's factor)
  double traceFree2[6][5];  // world entry (kSymmetric2's order) of a trace-free symmetric matrix from uu uv un vv vn
};
SOMICAGE_ISA_BEGIN  // the tables above are one type for every copy; what follows is per copy

// A face's derivatives at x (world coordinates), the compact form from which every output's gradient follows
// (integrateTriangleGradientsPortable below; the Somigliana rows add them directly, somigliana_gradient_row.h):
// per corner k, grad V_k = H_k, grad D_k = H_k n and d_c B_k,ab = (delta_ab (H_k n)_c - n_c H_k,ab) / 3 + Tb_k,cab;
// grad S = U and d_c M_ab = 3 M3_cab - delta_ac U_b - delta_bc U_a.
template <typename Scalar>
struct PortableTriangleGradientTensors {
  Scalar H[3][6];    // H_k, the Hessian of F_k = int phi_k/R (kSymmetric2's order)
  Scalar Hn[3][3];   // H_k n
  Scalar Tb[3][10];  // -h T_k / 3, T_k the third derivatives of F_k (kSymmetric3's order)
  Scalar U[3];       // int r/R^3
  Scalar M3[10];     // int r r r/R^5 (kSymmetric3's order)
};

namespace portable_detail {

constexpr double kThird = 1.0 / 3;  // a product rather than a division by 3 (a few times faster in packs)

// w = Q l for a vector, Q = [u v n] row-major.
template <typename Scalar>
SOMICAGE_HD inline void rotateVector(const double q[3][3], const Scalar l[3], Scalar w[3]) {
  for (int i = 0; i < 3; ++i) w[i] = q[i][0] * l[0] + q[i][1] * l[1] + q[i][2] * l[2];
}

// The distinct entries of a symmetric 3-tensor, in the order uuu, uuv, uun, uvv, uvn, unn, vvv, vvn, vnn, nnn (abc
// with a <= b <= c): kSymmetric3[a][b][c] is the place of entry abc, kSymmetric2 that of a symmetric matrix's.
constexpr int kSymmetric3[3][3][3] = {{{0, 1, 2}, {1, 3, 4}, {2, 4, 5}},
                                      {{1, 3, 4}, {3, 6, 7}, {4, 7, 8}},
                                      {{2, 4, 5}, {4, 7, 8}, {5, 8, 9}}};
constexpr int kSymmetric2[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};  // (xx, xy, xz, yy, yz, zz)
// The world entries of a trace-free symmetric 3-tensor that its table gives (all but xzz, yzz, zzz: those follow from
// the traces T_aii = 0, three additions instead of 21 multiply-adds).
constexpr int kTraceFreeRows[7] = {0, 1, 2, 3, 4, 6, 7};

// w = table l: a tensor's local entries l to its world ones w by one of PortableGradientFrame's tables.
template <int Rows, int N, typename Scalar>
SOMICAGE_HD inline void rotateByTable(const double (&table)[Rows][N], const Scalar (&l)[N], Scalar (&w)[Rows]) {
  for (int r = 0; r < Rows; ++r) {
    Scalar x = table[r][0] * l[0];
    for (int c = 1; c < N; ++c) x += table[r][c] * l[c];
    w[r] = x;
  }
}

}  // namespace portable_detail

// The tables of a face's frame (a degenerate frame's are never used).
SOMICAGE_HD inline void makeGradientFrame(const PortableTriangleFrame& f, PortableGradientFrame& g) {
  using portable_detail::kSymmetric2;
  using portable_detail::kSymmetric3;
  using portable_detail::kThird;
  const double q[3][3] = {{f.u[0], f.v[0], f.n[0]}, {f.u[1], f.v[1], f.n[1]}, {f.u[2], f.v[2], f.n[2]}};
  double sym2[6][6] = {};
  for (int w = 0; w < 10; ++w)
    for (int l = 0; l < 10; ++l) g.sym3[w][l] = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          sym2[kSymmetric2[i][j]][kSymmetric2[a][b]] += q[i][a] * q[j][b];
          for (int k = j; k < 3; ++k)
            for (int c = 0; c < 3; ++c)
              g.sym3[kSymmetric3[i][j][k]][kSymmetric3[a][b][c]] += q[i][a] * q[j][b] * q[k][c];
        }
  // Trace-free: unn = -(uuu + uvv), vnn = -(uuv + vvv), nnn = -(uun + vvn); nn = -(uu + vv).
  for (int r = 0; r < 7; ++r) {
    const double* s = g.sym3[portable_detail::kTraceFreeRows[r]];
    const double tf[7] = {s[0] - s[5], s[1] - s[8], s[3] - s[5], s[6] - s[8], s[2] - s[9], s[4], s[7] - s[9]};
    for (int c = 0; c < 7; ++c) g.traceFree3[r][c] = -kThird * tf[c];
  }
  for (int w = 0; w < 6; ++w) {
    const double* s = sym2[w];
    const double tf[5] = {s[0] - s[5], s[1], s[2], s[3] - s[5], s[4]};
    for (int c = 0; c < 5; ++c) g.traceFree2[w][c] = tf[c];
  }
}

// The derivative tensors of face f (not degenerate; tables = makeGradientFrame(f)) at x.
template <typename Scalar>
SOMICAGE_HD inline void triangleGradientTensorsPortable(const PortableTriangleFrame& f,
                                                        const PortableGradientFrame& tables, const Scalar x[3],
                                                        PortableTriangleGradientTensors<Scalar>& out) {
  using portable_detail::kThird;
  const Scalar rel[3] = {x[0] - f.origin[0], x[1] - f.origin[1], x[2] - f.origin[2]};
  const Scalar xu = rel[0] * f.u[0] + rel[1] * f.u[1] + rel[2] * f.u[2];
  const Scalar xv = rel[0] * f.v[0] + rel[1] * f.v[1] + rel[2] * f.v[2];
  const Scalar h = rel[0] * f.n[0] + rel[1] * f.n[1] + rel[2] * f.n[2];
  PortableTriangleMoments<Scalar> mo;
  triangleMomentsPortable(f, xu, xv, h, mo);
  const Scalar W = mo.W, hh = h * h;

  // Local second derivatives H_k of F_k (uu, uv, un, vv, vn; nn = -(uu + vv)) and h times the third ones T_k (the
  // in-plane entries uuu, uuv, uvv, vvv, uun, uvn, vvn; the others follow from the traces).
  Scalar H[3][5], T[3][7];
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

  // ---- To world coordinates: the tables (T's 10 entries from its 7 and the traces T_ann = -(T_auu + T_avv)) -------
  const double q[3][3] = {{f.u[0], f.v[0], f.n[0]}, {f.u[1], f.v[1], f.n[1]}, {f.u[2], f.v[2], f.n[2]}};
  for (int k = 0; k < 3; ++k) {
    const double g0 = f.grad[k][0], g1 = f.grad[k][1];
    Scalar* Tk = T[k];
    Tk[0] += g0 * h * H0[0], Tk[1] += g1 * h * H0[0], Tk[2] += g0 * h * H0[1], Tk[3] += g1 * h * H0[1];
    Tk[4] += g0 * h * H0[2], Tk[5] += g0 * h * H0[3], Tk[6] += g1 * h * H0[3];
    portable_detail::rotateByTable(tables.traceFree2, H[k], out.H[k]);
    Scalar Tw[7];
    portable_detail::rotateByTable(tables.traceFree3, T[k], Tw);
    Scalar* Tb = out.Tb[k];
    for (int r = 0; r < 7; ++r) Tb[portable_detail::kTraceFreeRows[r]] = Tw[r];
    Tb[5] = -(Tb[0] + Tb[3]), Tb[8] = -(Tb[1] + Tb[6]), Tb[9] = -(Tb[2] + Tb[7]);  // xzz, yzz, zzz
    const Scalar Hn[3] = {H[k][2], H[k][4], -(H[k][0] + H[k][3])};  // grad D_k (local)
    portable_detail::rotateVector(q, Hn, out.Hn[k]);
  }

  // S and M: U = grad S = int r/R^3 (local (J31, -W)) and the third moment int r r r/R^5.
  const Scalar Ul[3] = {mo.J31[0], mo.J31[1], -W};
  portable_detail::rotateVector(q, Ul, out.U);
  Scalar sumQ[4] = {0, 0, 0, 0};  // sum_e m_e,u Q_e,uu; m_e,v Q_e,uu; m_e,u Q_e,vv; m_e,v Q_e,vv
  for (int e = 0; e < 3; ++e) {
    sumQ[0] += f.m[e][0] * mo.Q[e][0], sumQ[1] += f.m[e][1] * mo.Q[e][0];
    sumQ[2] += f.m[e][0] * mo.Q[e][2], sumQ[3] += f.m[e][1] * mo.Q[e][2];
  }
  // J53_abc = (delta_ac J31_b + delta_bc J31_a - sum_e m_e,c Q_e,ab) / 3 (the divergence of d_a d_b/R^3).
  const Scalar Ml[10] = {(2 * mo.J31[0] - sumQ[0]) * kThird, -sumQ[1] * kThird, -mo.hJ52[0], -sumQ[2] * kThird,
                         -mo.hJ52[1], mo.h2J51[0], (2 * mo.J31[1] - sumQ[3]) * kThird, -mo.hJ52[2],
                         mo.h2J51[1], -mo.h3J50};
  portable_detail::rotateByTable(tables.sym3, Ml, out.M3);
}

// dx[i] = d/dx_i of every output of integrateTrianglePortable(f, x) (world coordinates), except solidAngle (0): the
// tensors above written out (one face on its own, as the tests compare it).
template <typename Scalar>
SOMICAGE_HD inline void integrateTriangleGradientsPortable(const PortableTriangleFrame& f, const Scalar x[3],
                                                           PortableTriangleIntegralsOf<Scalar> (&dx)[3]) {
  using portable_detail::kSymmetric2;
  using portable_detail::kSymmetric3;
  using portable_detail::kThird;
  if (f.degenerate) {  // all zeros, as the values are
    for (auto& d : dx) integrateTriangleLocalPortable(f, Scalar(0), Scalar(0), Scalar(0), d);
    return;
  }
  PortableGradientFrame tables;
  makeGradientFrame(f, tables);
  PortableTriangleGradientTensors<Scalar> t;
  triangleGradientTensorsPortable(f, tables, x, t);
  const double* n = f.n;
  for (int i = 0; i < 3; ++i) {
    PortableTriangleIntegralsOf<Scalar>& d = dx[i];
    d.solidAngle = 0;
    for (int k = 0; k < 3; ++k) {
      d.D[k] = t.Hn[k][i];
      for (int a = 0; a < 3; ++a) {
        d.V[k][a] = t.H[k][kSymmetric2[i][a]];
        for (int b = a; b < 3; ++b)
          d.B[k][a][b] = d.B[k][b][a] = t.Tb[k][kSymmetric3[i][a][b]] +
                                        ((a == b ? t.Hn[k][i] : Scalar(0)) - n[i] * t.H[k][kSymmetric2[a][b]]) * kThird;
      }
    }
    d.S = t.U[i];
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        Scalar m = 3 * t.M3[kSymmetric3[i][a][b]];
        if (i == a) m = m - t.U[b];
        if (i == b) m = m - t.U[a];
        d.M[a][b] = d.M[b][a] = m;
      }
  }
}

SOMICAGE_ISA_END
}  // namespace somicage

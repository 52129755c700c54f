// One point's three gradient rows d(row)/dx_a of the 3D Somigliana terms (somigliana_row_portable.h) from the
// closed-form derivatives of the triangle integrals (triangle_gradients_kernel.h). The rows are sums of the faces'
// integrals, linear in them (addFaceToSomiglianaRow), so each term's gradient is the same sum of the integrals'
// gradients; they are added here straight from each face's derivative tensors (PortableTriangleGradientTensors),
// without writing out the 3 x 46 derivatives of the integrals first.
#pragma once

#include "base/isa_namespace.h"
#include "coordinates/somigliana_row_portable.h"
#include "geometry/triangle_gradients_kernel.h"

namespace somicage {
SOMICAGE_ISA_BEGIN

// Overwrites `rows` with the three rows d(row of x)/dx_a (each numVertices * 10 + numFaces * 4 + 18 numbers)
// interleaved: entry k of row a at rows[3 * k + a], so that a face's three additions to an entry share a cache line.
// tables[j] = makeGradientFrame(faces[j].frame). Scalar: double, or simd::Pack for a pack of points
// (coordinate_gradients.cpp).
template <typename Scalar>
SOMICAGE_HD inline void integrateSomiglianaGradientRowPortable(const PortableFace* faces,
                                                               const PortableGradientFrame* tables, int numFaces,
                                                               int numVertices, const Scalar x[3], Scalar* rows) {
  using portable_detail::kSymmetric2;
  using portable_detail::kSymmetric3;
  using portable_detail::kThird;
  const long vertexColumns = static_cast<long>(numVertices) * kPortableVertexTerms;
  const long mainColumns = vertexColumns + static_cast<long>(numFaces) * kPortableFaceTerms;
  for (long k = 0; k < 3 * vertexColumns; ++k) rows[k] = 0;  // a face's own four terms are written, not added
  // The affine terms sum M_ab n_c over the faces: their gradients are sums of M3 n_c and U_b n_c, added up here and
  // written out once at the end.
  Scalar M3n[10][3], Un[3][3];
  for (int s = 0; s < 10; ++s) M3n[s][0] = M3n[s][1] = M3n[s][2] = 0;
  for (int b = 0; b < 3; ++b) Un[b][0] = Un[b][1] = Un[b][2] = 0;
  PortableTriangleGradientTensors<Scalar> d;
  const long termStride = 3L * numVertices;
  for (int j = 0; j < numFaces; ++j) {
    const PortableFace& face = faces[j];
    Scalar* f = rows + 3 * (vertexColumns + static_cast<long>(j) * kPortableFaceTerms);
    if (face.frame.degenerate) {
      for (int k = 0; k < 3 * kPortableFaceTerms; ++k) f[k] = 0;
      continue;
    }
    triangleGradientTensorsPortable(face.frame, tables[j], x, d);
    const double* n = face.frame.n;
    const double n3[3] = {n[0] * kThird, n[1] * kThird, n[2] * kThird};
    // The vertex terms (addFaceToSomiglianaRow): D_k, V_k x n, B_k's xx, yy, zz, xy, xz, yz.
    for (int k = 0; k < 3; ++k) {
      Scalar* t = rows + 3L * face.corners[k];
      const Scalar* H = d.H[k];
      const Scalar* Tb = d.Tb[k];
      for (int i = 0; i < 3; ++i) {
        const Scalar Hn = d.Hn[k][i], Hn3 = Hn * kThird;
        const Scalar Hi0 = H[kSymmetric2[i][0]], Hi1 = H[kSymmetric2[i][1]], Hi2 = H[kSymmetric2[i][2]];
        t[i] += Hn;
        t[termStride + i] += Hi1 * n[2] - Hi2 * n[1];
        t[2 * termStride + i] += Hi2 * n[0] - Hi0 * n[2];
        t[3 * termStride + i] += Hi0 * n[1] - Hi1 * n[0];
        t[4 * termStride + i] += Tb[kSymmetric3[i][0][0]] + (Hn3 - n3[i] * H[0]);
        t[5 * termStride + i] += Tb[kSymmetric3[i][1][1]] + (Hn3 - n3[i] * H[3]);
        t[6 * termStride + i] += Tb[kSymmetric3[i][2][2]] + (Hn3 - n3[i] * H[5]);
        t[7 * termStride + i] += Tb[kSymmetric3[i][0][1]] - n3[i] * H[1];
        t[8 * termStride + i] += Tb[kSymmetric3[i][0][2]] - n3[i] * H[2];
        t[9 * termStride + i] += Tb[kSymmetric3[i][1][2]] - n3[i] * H[4];
      }
    }
    // The face terms S and M n: d_i (M n)_a = 3 (M3 n)_ia - U_a n_i - delta_ia U.n.
    const Scalar Udotn = d.U[0] * n[0] + d.U[1] * n[1] + d.U[2] * n[2];
    for (int i = 0; i < 3; ++i) {
      f[i] = d.U[i];
      for (int a = 0; a < 3; ++a) {
        const Scalar M3n_ia =
            d.M3[kSymmetric3[i][a][0]] * n[0] + d.M3[kSymmetric3[i][a][1]] * n[1] + d.M3[kSymmetric3[i][a][2]] * n[2];
        Scalar g = 3 * M3n_ia - d.U[a] * n[i];
        if (i == a) g = g - Udotn;
        f[3 * (1 + a) + i] = g;
      }
    }
    for (int s = 0; s < 10; ++s)
      for (int c = 0; c < 3; ++c) M3n[s][c] += d.M3[s] * n[c];
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) Un[b][c] += d.U[b] * n[c];
  }
  // The affine terms (addAffineTerms): entry (a, pair bc) sums M_ab n_c + M_ac n_b (b != c) or M_ab n_b, and
  // sum_faces d_i M_ab n_c = 3 sum M3_iab n_c - delta_ia sum U_b n_c - delta_ib sum U_a n_c.
  const int first[6] = {0, 1, 2, 0, 0, 1}, second[6] = {0, 1, 2, 1, 2, 2};
  const auto dMn = [&](int i, int a, int b, int c) {
    Scalar g = 3 * M3n[kSymmetric3[i][a][b]][c];
    if (i == a) g = g - Un[b][c];
    if (i == b) g = g - Un[a][c];
    return g;
  };
  Scalar* affine = rows + 3 * mainColumns;
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 6; ++k) {
      const int b = first[k], c = second[k];
      for (int i = 0; i < 3; ++i)
        affine[3 * (a * 6 + k) + i] = b == c ? dMn(i, a, b, b) : dMn(i, a, b, c) + dMn(i, a, c, b);
    }
}

SOMICAGE_ISA_END
}  // namespace somicage

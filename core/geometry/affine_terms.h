// A face's share of a point's affine terms (somigliana_coordinates.h: affineTermCount), the one accumulation for
// the CPU integrator, the CUDA row kernel and the dual-number gradients. Host and device (SOMICAGE_HD).
#pragma once

#include "base/isa_namespace.h"
#include "base/portable.h"

namespace somicage {
SOMICAGE_ISA_BEGIN

// affine[(a * pairs + k) * stride] += (M)_ab n_c + (M)_ac n_b for the k-th pair bc (b != c), (M)_ab n_b for b = c;
// M symmetric (Dim by Dim, m[a][b]), n the face's unit normal. Pairs in B's order: xx, yy, zz, xy, xz, yz (3D) or
// xx, yy, xy (2D).
template <int Dim, typename Matrix, typename Scalar>
SOMICAGE_HD inline void addAffineTerms(const Matrix& m, const double* n, Scalar* affine, long stride = 1) {
  constexpr int pairs = Dim * (Dim + 1) / 2;
  const int first[6] = {0, 1, 2, 0, 0, 1}, second3[6] = {0, 1, 2, 1, 2, 2}, second2[3] = {0, 1, 1};
  for (int a = 0; a < Dim; ++a)
    for (int k = 0; k < pairs; ++k) {
      const int b = Dim == 3 ? first[k] : (k == 2 ? 0 : k), c = Dim == 3 ? second3[k] : second2[k];
      Scalar& out = affine[(a * pairs + k) * stride];
      out += m[a][b] * n[c];
      if (b != c) out += m[a][c] * n[b];
    }
}

SOMICAGE_ISA_END
}  // namespace somicage

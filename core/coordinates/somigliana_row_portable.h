// One point's row of nu-independent 3D Somigliana terms in the layout of C (core/deform/coordinate_layout.h: 10 terms
// per cage vertex, term-major, then 4 per face; somiglianaLayout), summed face by face in the same order and with the
// same arithmetic as integrateSomiglianaCoordinates' closed-form path. Host and device (SOMICAGE_HD).
#pragma once

#include "base/isa_namespace.h"
#include "geometry/affine_terms.h"
#include "geometry/triangle_integrals_kernel.h"

namespace somicage {

// A cage face as the kernels need it: its frame (which holds the unit normal n) and its corner vertices.
struct PortableFace {
  PortableTriangleFrame frame;
  int corners[3];
};
SOMICAGE_ISA_BEGIN  // the face is one type for every copy; the functions below are per copy

constexpr int kPortableVertexTerms = 10;  // vertexTermCount(3)
constexpr int kPortableFaceTerms = 4;     // faceTermCount(3)
constexpr int kPortableAffineTerms = 18;  // affineTermCount(3)

// Adds face j's integrals I (of one point; numFaces faces in the cage) to that point's row: entry k at row[k * stride] (stride 1 for a contiguous
// row; the kernels use the number of points, so that neighbouring threads write neighbouring addresses). The sums
// are linear in I, so the gradient rows (somigliana_gradient_row.h) add the integrals' derivatives the same way.
template <typename Scalar>
SOMICAGE_HD inline void addFaceToSomiglianaRow(const PortableFace& face, int j, int numFaces, int numVertices,
                                               const PortableTriangleIntegralsOf<Scalar>& I, Scalar* row,
                                               long stride) {
  const int vertexColumns = numVertices * kPortableVertexTerms;
  const long mainColumns = vertexColumns + static_cast<long>(numFaces) * kPortableFaceTerms;
  const double* n = face.frame.n;
  for (int k = 0; k < 3; ++k) {
    // Term m of the corner at column m * numVertices + corner (term-major).
    Scalar* t = row + static_cast<long>(face.corners[k]) * stride;
    const long termStride = static_cast<long>(numVertices) * stride;
    const Scalar* V = I.V[k];
    const Scalar(*B)[3] = I.B[k];
    t[0] += I.D[k];
    // omega = V x n: (n V^T - V n^T) w = (V x n) x w
    t[1 * termStride] += V[1] * n[2] - V[2] * n[1];
    t[2 * termStride] += V[2] * n[0] - V[0] * n[2];
    t[3 * termStride] += V[0] * n[1] - V[1] * n[0];
    t[4 * termStride] += B[0][0], t[5 * termStride] += B[1][1], t[6 * termStride] += B[2][2];
    t[7 * termStride] += B[0][1], t[8 * termStride] += B[0][2], t[9 * termStride] += B[1][2];
  }
  Scalar* f = row + (vertexColumns + static_cast<long>(j) * kPortableFaceTerms) * stride;
  f[0] += I.S;
  for (int i = 0; i < 3; ++i) f[(1 + i) * stride] += I.M[i][0] * n[0] + I.M[i][1] * n[1] + I.M[i][2] * n[2];
  addAffineTerms<3>(I.M, n, row + mainColumns * stride, stride);
}

// Overwrites the row of point x: numVertices * 10 + numFaces * 4 + 18 numbers (the main block, then the affine
// terms), entry k at row[k * stride] (addFaceToSomiglianaRow). Returns the generalised winding number
// -sum_j W_j / 4pi. Scalar: double, or simd::Pack for a pack of points at once (simd_pack.h; the CPU precompute's
// rows, somigliana_coordinates.cpp).
template <typename Scalar>
SOMICAGE_HD inline Scalar integrateSomiglianaRowPortable(const PortableFace* faces, int numFaces, int numVertices,
                                                         const Scalar x[3], Scalar* row, long stride) {
  const long columns = numVertices * kPortableVertexTerms + static_cast<long>(numFaces) * kPortableFaceTerms;
  for (long k = 0; k < columns + kPortableAffineTerms; ++k) row[k * stride] = 0;
  Scalar angleSum = 0;
  PortableTriangleIntegralsOf<Scalar> I;
  for (int j = 0; j < numFaces; ++j) {
    const PortableFace& face = faces[j];
    if (face.frame.degenerate) continue;
    integrateTrianglePortable(face.frame, x, I);
    addFaceToSomiglianaRow(face, j, numFaces, numVertices, I, row, stride);
    angleSum += I.solidAngle;
  }
  return -angleSum / (4 * 3.14159265358979323846);
}

SOMICAGE_ISA_END
}  // namespace somicage

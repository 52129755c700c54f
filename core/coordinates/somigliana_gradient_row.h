// One point's three gradient rows d(row)/dx_a of the 3D Somigliana terms (somigliana_row_portable.h) from the
// closed-form derivatives of the triangle integrals (triangle_gradients_kernel.h): the rows are sums of the faces'
// integrals, linear in them, so each face's derivatives are added with the rows' own accumulation.
#pragma once

#include "base/isa_namespace.h"
#include "coordinates/somigliana_row_portable.h"
#include "geometry/triangle_gradients_kernel.h"

namespace somicage {
SOMICAGE_ISA_BEGIN

// Overwrites `rows` with the three rows d(row of x)/dx_a (each numVertices * 10 + numFaces * 4 + 18 numbers)
// interleaved: entry k of row a at rows[3 * k + a], so that a face's three additions to an entry share a cache line.
// Scalar: double, or simd::Pack for a pack of points (coordinate_gradients.cpp).
template <typename Scalar>
SOMICAGE_HD inline void integrateSomiglianaGradientRowPortable(const PortableFace* faces, int numFaces,
                                                               int numVertices, const Scalar x[3], Scalar* rows) {
  const long columns =
      numVertices * kPortableVertexTerms + static_cast<long>(numFaces) * kPortableFaceTerms + kPortableAffineTerms;
  for (long k = 0; k < 3 * columns; ++k) rows[k] = 0;
  PortableTriangleIntegralsOf<Scalar> dx[3];
  for (int j = 0; j < numFaces; ++j) {
    const PortableFace& face = faces[j];
    if (face.frame.degenerate) continue;
    integrateTriangleGradientsPortable(face.frame, x, dx);
    for (int a = 0; a < 3; ++a) addFaceToSomiglianaRow(face, j, numFaces, numVertices, dx[a], rows + a, 3);
  }
}

SOMICAGE_ISA_END
}  // namespace somicage

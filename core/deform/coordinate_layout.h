// The column layout of a method's coordinate matrix C (frame_evaluation.h): its one home. Integrators write rows
// in it, deformers build their weight rows from it, the GPU backends upload it and the memory estimate sizes it.
//
//   [ vertex terms, term-major | face terms, face-major | tail ]
//   vertex i, term k:  column k * #V + i        (each term of all vertices is one contiguous range, which a frame
//                                                reads in one pass: e.g. only the antisymmetric terms for A)
//   face j, term k:    column #V * vertexTerms + j * faceTerms + k
//   tail column k:     column mainColumns() + k (per-point numbers such as [x | 1], see the method)
// An integrator writes a point's main block followed by its tailIntegrals (per-point integrals that belong to no
// single vertex or face): integralColumns() numbers; the method places them in its tail.
//
// Sparse rows (rowEntries > 0): a method whose rows have few nonzeros (Phong: a point's simplex's d + 1 vertices
// times d + 1 terms, of (d + 1) #N columns) stores each row as rowEntries (column, value) pairs in these same column
// numbers (frame_evaluation.h: FrameCoordinates::entryColumns); every frame evaluator reads that form.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>

namespace somicage {

// Rows of C (and of the coordinates integrators produce) are contiguous.
using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct CoordinateLayout {
  int numVertices = 0;
  int numFaces = 0;
  int vertexTerms = 0;  // numbers per cage vertex
  int faceTerms = 0;    // numbers per cage face
  int tailColumns = 0;  // numbers per point after the vertex and face blocks
  int tailIntegrals = 0;  // of them, integrals the integrator writes after the main block (Somigliana's affine terms)
  int rowEntries = 0;     // > 0: C is stored as sparse rows of this many (column, value) pairs each; 0: dense

  int vertexColumns() const { return numVertices * vertexTerms; }
  int mainColumns() const { return vertexColumns() + numFaces * faceTerms; }  // K_main of frame_evaluation.h
  int columns() const { return mainColumns() + tailColumns; }
  int integralColumns() const { return mainColumns() + tailIntegrals; }  // an integrator's row
  int vertexColumn(int i, int k) const { return k * numVertices + i; }
  int faceColumn(int j, int k) const { return vertexColumns() + j * faceTerms + k; }
  int tailColumn(int k) const { return mainColumns() + k; }

  // Bytes of C for `points` rows in float or double (sparse rows: each entry's value and its 32-bit column).
  std::size_t bytes(std::size_t points, bool floatStorage) const {
    const std::size_t value = floatStorage ? sizeof(float) : sizeof(double);
    if (rowEntries > 0) return points * static_cast<std::size_t>(rowEntries) * (value + sizeof(std::int32_t));
    return points * static_cast<std::size_t>(columns()) * value;
  }
};

}  // namespace somicage

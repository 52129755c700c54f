// How every deformation method evaluates a frame, so that one CPU kernel (here) and one GPU kernel serve them all:
//
//   y_p   = C_p,main . W_main  (added to the output columns from W.mainOffset on)  +  C_p,tail . W_tail
//   out_p = y_p                                       when the frame has d outputs (Green, mean value)
//   out_p = o + T_p^-1 b_p                            when it has d^2 + d outputs (Somigliana, Eq. 11), with
//           b_p = y_p[d^2 : d^2 + d] and T_p = S + A split into its symmetric and antisymmetric parts:
//             3D: S = (xx, yy, zz, xy, xz, yz) = y[0..5], A w = omega x w with omega = y[6..8];
//             2D: S = (xx, yy, xy) = y[0..2], A = [[0, y3], [-y3, 0]].
//           The split lets each output touch only the coordinates it needs (S the symmetric terms, A the
//           antisymmetric ones): tOutputsFromMatrix converts a matrix into them. o is the frame's origin (the
//           posed cage's centroid for Somigliana), b is built relative to it: far from the coordinate origin
//           that keeps float storage accurate, and a singular T (frame_point_kernel.h) maps b = 0 to o.
//
// C (#P + 2 #E by K_main + K_tail) is fixed after precompute; W is rebuilt for every frame from the posed cage and
// the parameters, and is small (K by at most 12). A frame therefore reads C once: its cost is memory bandwidth.
//
// Exterior points (outside the cage, on it, or with unreliable integrals; core/deform/exterior_points.h) add two rows
// each after the #P point rows: exterior point e (point p, weight w) has its proxy x_in at row P + 2e and the
// anchor [0 | x_in | 1] at row P + 2e + 1, and its own row is [0 | x | 1]. After every row is evaluated,
//   out_p += w (out_{P+2e} - out_{P+2e+1})        i.e.  x~ = S(x) + w(d) [phi(x_in) - S(x_in)]
// and only the #P point rows are returned.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "deform/frame_finish.h"

namespace somicage {

template <typename Scalar>
using CoordinateMatrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// One exterior point: its index p < #P and its weight w(d) in [0, 1] (see above and core/deform/exterior_points.h).
struct ExteriorBlend {
  int point = 0;
  double weight = 0;
};

// The coordinate matrix C, stored in double or in float (exactly one of the two is non-empty). Float halves the
// memory and the bytes read per frame at ~1e-7 relative error per entry: the editor's choice; the command line
// keeps double.
// Dense (entryColumns empty): doubles/floats are C. Sparse rows (a layout with rowEntries > 0, coordinate_layout.h):
// doubles/floats hold rowEntries values per row and entryColumns their columns in C, i.e.
//   C(r, entryColumns(r, k)) += values(r, k)        (unused entries: value 0, any valid column)
// Every evaluator reads both forms (evaluateFrame here, the OpenGL and CUDA kernels), so a method picks its form
// by its layout alone.
struct FrameCoordinates {
  CoordinateMatrix<double> doubles;
  CoordinateMatrix<float> floats;
  int mainColumns = 0;                        // K_main: the remaining columns are the tail
  std::vector<ExteriorBlend> exteriorBlends;  // #E, by ascending point; their rows follow the #P point rows
  CoordinateMatrix<std::int32_t> entryColumns;  // sparse rows: #P + 2 #E by rowEntries; empty: dense
  int sparseColumns = 0;                        // sparse rows: C's columns (K_main + K_tail)

  bool isFloat() const { return floats.size() > 0 || doubles.size() == 0; }
  bool isSparse() const { return entryColumns.size() > 0; }
  int rows() const { return static_cast<int>(isFloat() ? floats.rows() : doubles.rows()); }  // #P + 2 #E
  int numPoints() const { return rows() - 2 * static_cast<int>(exteriorBlends.size()); }     // #P
  // Numbers stored per row: C's columns, or the entries of a sparse row.
  int storedColumns() const { return static_cast<int>(isFloat() ? floats.cols() : doubles.cols()); }
  int columns() const { return isSparse() ? sparseColumns : storedColumns(); }  // C's columns
  std::size_t bytes() const {
    return (isFloat() ? floats.size() * sizeof(float) : doubles.size() * sizeof(double)) +
           static_cast<std::size_t>(entryColumns.size()) * sizeof(std::int32_t);
  }
};

// C in the requested storage (the double matrix is moved, or converted to float).
FrameCoordinates makeFrameCoordinates(CoordinateMatrix<double> C, int mainColumns, bool floatStorage);

// The dense C of sparse rows (a copy of dense ones), in the same storage: for tests and tools that compare the forms.
FrameCoordinates denseFrameCoordinates(const FrameCoordinates& C);

struct FrameWeights {
  FrameFinish finish = FrameFinish::Linear;  // the method's (MethodDescriptor::finish)
  int outputs = 0;         // frameOutputs(finish, d): d, or d * d + d for a per-point solve
  int mainOffset = 0;      // the first output column that `main` contributes to
  Eigen::MatrixXd main;    // K_main by (outputs - mainOffset)
  Eigen::MatrixXd tail;    // K_tail by outputs
  Eigen::VectorXd origin;  // o (d) for a per-point solve; empty means 0
};

// The T outputs (d^2 numbers, layout above) of a d by d matrix M.
Eigen::VectorXd tOutputsFromMatrix(const Eigen::MatrixXd& M);

// out (#P by d, resized) from C and W as described above, with OpenMP over fixed blocks of points, so the result
// does not depend on the thread count (threads = 0: the OpenMP default). Exterior points included.
void evaluateFrame(const FrameCoordinates& C, const FrameWeights& W, int dim, int threads, Eigen::MatrixXd& out);

// The raw outputs y = C_p W (before the per-point solve and the exterior blend) of every row of C (#P + 2 #E by
// W.outputs, resized), with the kernel and the thread partition of evaluateFrame; the deformation gradient
// (jacobian.h) applies the same W to the gradients of C's rows.
void evaluateFrameOutputs(const FrameCoordinates& C, const FrameWeights& W, int threads, CoordinateMatrix<double>& y);

// The exterior blend on out = every row of C evaluated (#P + 2 #E by d): adds w (proxy - anchor) to each exterior
// point's row and keeps the first #P rows.
void blendExteriorPoints(const std::vector<ExteriorBlend>& blends, Eigen::MatrixXd& out);

}  // namespace somicage

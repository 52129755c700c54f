// One point of a frame (frame_evaluation.h) in plain C++: the partial sums y = C_p W of one lane of a CUDA warp,
// and the per-point finish (o + T_p^-1 b_p, Eq. 11), which the CPU kernel (frame_evaluation.cpp) calls too.
// tests/core/cuda_portable_frame_test.cpp runs the sums on the host (32 lanes summed in a loop) against
// evaluateFrame; the CUDA kernel adds only the warp's shuffle reduction.
#pragma once

#include <math.h>
#include <stdint.h>

#include "base/portable.h"
#include "deform/frame_finish.h"

namespace somicage {

constexpr int kPortableMaxOutputs = 12;  // d * d + d for d = 3

// The weights of one frame for the kernels: one row of outputs per column of C. main is mainColumns by
// (outputs - mainOffset) and feeds outputs [mainOffset, outputs); tail is (columns - mainColumns) by outputs.
struct PortableFrameWeights {
  const double* main;
  const double* tail;
  int columns, mainColumns, mainOffset, outputs;
  double origin[3];  // FrameWeights::origin (zeros when it is empty)
  FrameFinish finish;
};

// Adds to y (kPortableMaxOutputs) the terms of row c (columns entries) in the columns lane, lane + lanes, ...
template <typename Scalar>
SOMICAGE_HD inline void addFramePartialSums(const Scalar* c, const PortableFrameWeights& W, int lane, int lanes,
                                            double* y) {
  const int mainOutputs = W.outputs - W.mainOffset;
  for (int k = lane; k < W.mainColumns; k += lanes) {
    const double ck = static_cast<double>(c[k]);
    const double* w = W.main + static_cast<long>(k) * mainOutputs;
#ifdef __CUDA_ARCH__
#pragma unroll
#endif
    for (int o = 0; o < kPortableMaxOutputs; ++o)  // fixed bounds: y stays in registers on the device
      if (o >= W.mainOffset && o < W.outputs) y[o] += ck * w[o - W.mainOffset];
  }
  for (int k = W.mainColumns + lane; k < W.columns; k += lanes) {
    const double ck = static_cast<double>(c[k]);
    const double* w = W.tail + static_cast<long>(k - W.mainColumns) * W.outputs;
#ifdef __CUDA_ARCH__
#pragma unroll
#endif
    for (int o = 0; o < kPortableMaxOutputs; ++o)
      if (o < W.outputs) y[o] += ck * w[o];
  }
}

// The same for a sparse row (coordinate_layout.h): its entries lane, lane + lanes, ... of `entries`, entry k being
// c[k] at column columns[k] of C.
template <typename Scalar>
SOMICAGE_HD inline void addSparseFramePartialSums(const Scalar* c, const int32_t* columns, int entries,
                                                  const PortableFrameWeights& W, int lane, int lanes, double* y) {
  const int mainOutputs = W.outputs - W.mainOffset;
  for (int k = lane; k < entries; k += lanes) {
    const double ck = static_cast<double>(c[k]);
    const int column = columns[k];
    const bool main = column < W.mainColumns;
    const double* w = main ? W.main + static_cast<long>(column) * mainOutputs
                           : W.tail + static_cast<long>(column - W.mainColumns) * W.outputs;
    const int first = main ? W.mainOffset : 0;  // W_main feeds the outputs from mainOffset on
#ifdef __CUDA_ARCH__
#pragma unroll
#endif
    for (int o = 0; o < kPortableMaxOutputs; ++o)
      if (o >= first && o < W.outputs) y[o] += ck * w[o - first];
  }
}

namespace portable_detail {

// x = M^-1 v by the adjugate (M d by d, d = 2 or 3); returns det M (x is not finite when it is 0).
template <int Dim, typename Scalar>
SOMICAGE_HD inline Scalar solveByAdjugate(const Scalar (&M)[Dim][Dim], const Scalar* v, Scalar* x) {
  if constexpr (Dim == 3) {
    Scalar adj[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
        adj[i][j] = M[i1][j1] * M[i2][j2] - M[i1][j2] * M[i2][j1];
      }
    const Scalar det = M[0][0] * adj[0][0] + M[0][1] * adj[1][0] + M[0][2] * adj[2][0];
    const Scalar invDet = 1 / det;
    for (int i = 0; i < 3; ++i) x[i] = (adj[i][0] * v[0] + adj[i][1] * v[1] + adj[i][2] * v[2]) * invDet;
    return det;
  } else {
    const Scalar det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    const Scalar invDet = 1 / det;
    x[0] = (M[1][1] * v[0] - M[0][1] * v[1]) * invDet;
    x[1] = (M[0][0] * v[1] - M[1][0] * v[0]) * invDet;
    return det;
  }
}

}  // namespace portable_detail

// |det T| at most this times |T|_F^d: T(x) is singular to rounding (Eq. 11 has no solution there).
constexpr double kSingularT = 1e-12;

// The point from its summed outputs y (the one switch on the finish of the CPU, CUDA and J): y itself for
// FrameFinish::Linear, else (SolveT) o + T^-1 b with T = S + A (layout in
// frame_evaluation.h), o the frame's origin (b is relative to it), T inverted by its adjugate as Eigen does for
// fixed 2x2 and 3x3 matrices. Where T is singular to rounding -- local rotations can cancel in
// T = sum_i R_i T_i R_i^T, e.g. on a cage collapsed to a point -- the regularised least-squares
// x = (T^T T + mu I)^-1 T^T b, mu = kSingularT |T|_F^2, keeps the point finite: at o when b = 0.
// Scalar: double, or dual numbers (dual_number.h) whose gradients are those of y: the result's gradient is then the
// derivative of Eq. 11's solve, T^-1 (b' - T' T^-1 b) (the deformation gradient of jacobian.h).
template <int Dim, typename Scalar>
SOMICAGE_HD inline void finishFramePoint(const Scalar* y, FrameFinish finish, const double* origin, Scalar* result) {
  if (finish == FrameFinish::Linear) {
    for (int a = 0; a < Dim; ++a) result[a] = y[a];
    return;
  }
  Scalar T[Dim][Dim];
  if constexpr (Dim == 3) {
    const Scalar rows[3][3] = {
        {y[0], y[3] - y[8], y[4] + y[7]}, {y[3] + y[8], y[1], y[5] - y[6]}, {y[4] - y[7], y[5] + y[6], y[2]}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) T[i][j] = rows[i][j];
  } else {
    T[0][0] = y[0], T[0][1] = y[2] + y[3], T[1][0] = y[2] - y[3], T[1][1] = y[1];
  }
  const Scalar* b = y + Dim * Dim;
  Scalar norm2 = 0;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) norm2 += T[i][j] * T[i][j];
  const Scalar det = portable_detail::solveByAdjugate<Dim>(T, b, result);
  const Scalar scale = Dim == 3 ? norm2 * sqrt(norm2) : norm2;  // |T|_F^d
  if (!(fabs(det) > kSingularT * scale)) {
    Scalar N[Dim][Dim], rhs[Dim];  // T^T T + mu I and T^T b
    for (int i = 0; i < Dim; ++i) {
      rhs[i] = 0;
      for (int k = 0; k < Dim; ++k) rhs[i] += T[k][i] * b[k];
      for (int j = 0; j < Dim; ++j) {
        N[i][j] = i == j ? kSingularT * norm2 : Scalar(0.0);
        for (int k = 0; k < Dim; ++k) N[i][j] += T[k][i] * T[k][j];
      }
    }
    if (!(norm2 > 0) || !(portable_detail::solveByAdjugate<Dim>(N, rhs, result) != 0))
      for (int a = 0; a < Dim; ++a) result[a] = 0;
  }
  for (int a = 0; a < Dim; ++a) result[a] += origin[a];
}

}  // namespace somicage

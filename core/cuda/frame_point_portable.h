// One point of a frame (frame_evaluation.h) in plain C++ for the CUDA frame kernel, host-testable like the
// integrals: the partial sums y = C_p W of one lane of a warp, and the per-point finish (T_p^-1 b_p, Eq. 11).
// tests/core/cuda_portable_integrals_test.cpp runs both on the host (32 lanes summed in a loop) against
// evaluateFrame; the kernel adds only the warp's shuffle reduction.
#pragma once

#include "portable.h"

namespace somicage {

constexpr int kPortableMaxOutputs = 12;  // d * d + d for d = 3

// The weights of one frame for the kernels: one row of outputs per column of C. main is mainColumns by
// (outputs - mainOffset) and feeds outputs [mainOffset, outputs); tail is (columns - mainColumns) by outputs.
struct PortableFrameWeights {
  const double* main;
  const double* tail;
  int columns, mainColumns, mainOffset, outputs;
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

// The point from its summed outputs y: y itself for d outputs, else T^-1 b with T = S + A (layout in
// frame_evaluation.h) inverted by its adjugate, as Eigen does for fixed 2x2 and 3x3 matrices.
template <int Dim>
SOMICAGE_HD inline void finishFramePoint(const double* y, int outputs, double* result) {
  if (outputs == Dim) {
    for (int a = 0; a < Dim; ++a) result[a] = y[a];
    return;
  }
  const double* b = y + Dim * Dim;
  if constexpr (Dim == 3) {
    const double T[3][3] = {{y[0], y[3] - y[8], y[4] + y[7]},
                            {y[3] + y[8], y[1], y[5] - y[6]},
                            {y[4] - y[7], y[5] + y[6], y[2]}};
    double adj[3][3];  // inverse = adj / det
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
        adj[i][j] = T[i1][j1] * T[i2][j2] - T[i1][j2] * T[i2][j1];
      }
    const double invDet = 1 / (T[0][0] * adj[0][0] + T[0][1] * adj[1][0] + T[0][2] * adj[2][0]);
    for (int i = 0; i < 3; ++i) result[i] = (adj[i][0] * b[0] + adj[i][1] * b[1] + adj[i][2] * b[2]) * invDet;
  } else {
    const double t00 = y[0], t01 = y[2] + y[3], t10 = y[2] - y[3], t11 = y[1];
    const double invDet = 1 / (t00 * t11 - t01 * t10);
    result[0] = (t11 * b[0] - t01 * b[1]) * invDet;
    result[1] = (t00 * b[1] - t10 * b[0]) * invDet;
  }
}

}  // namespace somicage

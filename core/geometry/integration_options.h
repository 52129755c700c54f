// How a precompute integrates coordinates, and the integrator it uses (the CPU's, or a device's injected through
// PrecomputeOptions, e.g. cuda_backend.h), apart from any one method's formulas.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "base/progress.h"
#include "geometry/cage.h"

namespace somicage {

// How the triangle integrals are evaluated (3D). The closed form is exact; Gauss is the paper's baseline.
struct IntegrationOptions {
  enum class Rule { ClosedForm, Gauss };
  Rule rule = Rule::ClosedForm;
  int gaussPointsPerSide = 50;  // N: 3 N^2 points per triangle (the paper uses N = 50, 7500 points)
  int threads = 0;              // OpenMP threads; 0 = the OpenMP default
  // The closed form one point at a time (the reference), not in SIMD packs of points (simd_pack.h), which agree with
  // it to a few units of rounding; for tests.
  bool scalarKernel = false;
};

// Receives each point's row of the integrals of C (coordinate_layout.h: CoordinateLayout::integralColumns()
// numbers, in that layout) and its generalised winding number. Called from worker threads, once per point: it
// may write per-point storage without locking. The row buffer is reused after the call returns.
using CoordinateRowSink = std::function<void(int point, const double* row, double winding)>;

// Integrates the rows of every point (#P by d) and streams them to the sink; throws Cancelled when progress
// returns false. Methods that integrate row by row (Somigliana) call the one in PrecomputeOptions, or the CPU's.
using RowIntegrator =
    std::function<void(const Cage& cage, const Eigen::MatrixXd& points, const IntegrationOptions& options,
                       const ProgressCallback& progress, const CoordinateRowSink& sink)>;

}  // namespace somicage

// The CUDA backend (core/cuda/cuda_backend.h) against the CPU engine. The comparisons need a device and skip
// visibly without one ("no CUDA device: <reason>"); the status and error-path tests run everywhere.
//
// Tolerances: a frame from float coordinates within 1e-5 cage diameters of the CPU frame (both read the same
// float C; the GPU accumulates in double, the CPU partly in float), from double coordinates within 1e-9; the
// precompute's rows within 1e-9 relative to the row's largest entry (the same double formulas; only the device's
// fused multiply-adds and math library round differently); against the independent quadrature of
// core/reference/ (not the CPU), T_i and K_j n_j within 1e-10 relative.
#include "cuda/cuda_backend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/frame_cases.h"
#include "core/reference/portable_row_check.h"
#include "core/test_shapes.h"
#include "deform/deformer.h"
#include "methods/method_descriptors.h"

namespace somicage {
namespace {

#define SKIP_WITHOUT_DEVICE() \
  if (!cudaStatus().available) GTEST_SKIP() << "no CUDA device: " << cudaStatus().reason

Eigen::MatrixXd randomPointsIn(const Cage& cage, int count, double shrink, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  Eigen::MatrixXd points(count, cage.dim());
  for (int p = 0; p < count; ++p)
    for (int a = 0; a < cage.dim(); ++a) points(p, a) = shrink * unit(rng);
  return points;
}

TEST(CudaBackend, StatusExplainsItself) {
  const CudaStatus& status = cudaStatus();
  if (status.available) {
    EXPECT_FALSE(status.deviceName.empty());
    EXPECT_GT(status.memoryBytes, 0u);
    EXPECT_GE(status.computeCapability, 50);
    EXPECT_TRUE(status.reason.empty());
  } else {
    EXPECT_FALSE(status.reason.empty());
#ifndef SOMICAGE_HAVE_CUDA
    EXPECT_NE(status.reason.find("built without CUDA"), std::string::npos) << status.reason;
#endif
  }
  std::printf("CUDA status: %s\n", status.available ? status.deviceName.c_str() : status.reason.c_str());
}

TEST(CudaBackend, WithoutDeviceEveryCallThrowsCudaError) {
  if (cudaStatus().available) GTEST_SKIP() << "a CUDA device is present: " << cudaStatus().deviceName;
  const Cage cage = test::makeCube();
  const auto deformer = makeDeformer(methods::somigliana(), cage, randomPointsIn(cage, 8, 0.5, 1));
  EXPECT_THROW(CudaFrameEvaluator(deformer->frameCoordinates(), 3), CudaError);
  EXPECT_THROW(integrateSomiglianaCoordinatesCuda(cage, randomPointsIn(cage, 4, 0.5, 2), noProgress,
                                                  [](int, const double*, double) {}),
               CudaError);
}

void expectFramesMatch(const Cage& cage, const Eigen::MatrixXd& points) {
  test::expectFramesMatchCpu(cage, points, [&](const CageDeformer& deformer, const FrameWeights& W) {
    CudaFrameEvaluator gpu(deformer.frameCoordinates(), cage.dim());
    Eigen::MatrixXd out;
    gpu.evaluate(W, out);
    return out;
  });
}

TEST(CudaBackend, FrameMatchesCpu3D) {
  SKIP_WITHOUT_DEVICE();
  const Cage cage = test::makeBumpySphere(1);
  Eigen::MatrixXd points = randomPointsIn(cage, 3000, 0.4, 3);
  points.row(0) << 2.5, 0.1, -0.2;  // outside the cage: the exterior rule, blended on the host
  expectFramesMatch(cage, points);
}

TEST(CudaBackend, FrameMatchesCpu2D) {
  SKIP_WITHOUT_DEVICE();
  const Cage cage = makePolygonCage(test::lLoop());
  Eigen::MatrixXd points = randomPointsIn(cage, 2000, 0.45, 4).array() + 0.5;  // inside the lower-left square
  expectFramesMatch(cage, points);
}

TEST(CudaBackend, PrecomputeMatchesCpu) {
  SKIP_WITHOUT_DEVICE();
  const Cage cage = test::makeBumpySphere(2);
  Eigen::MatrixXd points = randomPointsIn(cage, 5000, 0.4, 5);
  points.row(0) << 0, 0, 0;
  points.row(1) << 3, 0, 0;
  const SomiglianaCoordinates cpu = computeSomiglianaCoordinates(cage, points);
  RowMatrixXd gpu(cpu.values.rows(), cpu.values.cols());
  Eigen::VectorXd winding(points.rows());
  integrateSomiglianaCoordinatesCuda(cage, points, noProgress, [&](int p, const double* row, double w) {
    gpu.row(p) = Eigen::Map<const Eigen::RowVectorXd>(row, gpu.cols());
    winding(p) = w;
  });
  double worst = 0;
  for (int p = 0; p < points.rows(); ++p)
    worst = std::max(worst,
                     (gpu.row(p) - cpu.values.row(p)).cwiseAbs().maxCoeff() / cpu.values.row(p).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 1e-9) << "largest relative difference of a row";
  EXPECT_LE((winding - cpu.winding).cwiseAbs().maxCoeff(), 1e-9);
}

// The device precompute against the independent reference (adaptive Gauss-Legendre quadrature of Eqs. 3-4), not
// only against the CPU, which shares the device's triangle kernel: each row is turned back into T_i and K_j n_j.
TEST(CudaBackend, PrecomputeMatchesTheReferenceQuadrature) {
  SKIP_WITHOUT_DEVICE();
  const Cage cage = test::makeBumpySphere(1);
  const Eigen::MatrixXd points = randomPointsIn(cage, 40, 0.45, 6);
  const int columns = 10 * cage.numVertices() + 4 * cage.numFaces() + 18;  // and the 18 affine terms (issue 26)
  std::vector<std::vector<double>> rows(points.rows());
  std::vector<double> winding(points.rows());
  integrateSomiglianaCoordinatesCuda(cage, points, noProgress, [&](int p, const double* row, double w) {
    rows[p].assign(row, row + columns);
    winding[p] = w;
  });
  double worst = 0, worstWinding = 0, worstAffine = 0;
  for (int p = 0; p < points.rows(); ++p) {
    const reference::RowComparison c =
        reference::compareRowWithReference(cage, points.row(p).transpose(), rows[p].data(), 1, winding[p]);
    worst = std::max(worst, c.coordinates), worstWinding = std::max(worstWinding, c.winding);
    worstAffine = std::max(worstAffine, c.affine);
  }
  EXPECT_LE(worst, 1e-10) << "largest relative difference of T_i, K_j n_j";
  EXPECT_LE(worstWinding, 1e-10);
  EXPECT_LE(worstAffine, 1e-10) << "largest relative difference of the affine terms' sum_j K_j sigma n_j";
}

}  // namespace
}  // namespace somicage

// The CUDA backend (core/cuda/cuda_backend.h) against the CPU engine. The comparisons need a device and skip
// visibly without one ("no CUDA device: <reason>"); the status and error-path tests run everywhere.
//
// Tolerances: a frame from float coordinates within 1e-5 cage diameters of the CPU frame (both read the same
// float C; the GPU accumulates in double, the CPU partly in float), from double coordinates within 1e-9; the
// precompute's rows within 1e-9 relative to the row's largest entry (the same double formulas; only the device's
// fused multiply-adds and math library round differently).
#include "cuda/cuda_backend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/frame_cases.h"
#include "core/test_shapes.h"
#include "deformer.h"
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

}  // namespace
}  // namespace somicage

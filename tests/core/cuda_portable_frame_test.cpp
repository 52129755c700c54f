// The CUDA frame kernel's per-point code (core/deform/frame_point_kernel.h), run on the host with the 32 lanes of a
// warp summed in a loop, against the CPU frame (CageDeformer::deform). This checks the kernel's weight layout and
// its T^-1 b solve without a GPU; only the shuffle reduction is device-only. Sparse rows (Phong) run the sparse
// kernel's sums (addSparseFramePartialSums), dense rows the dense one's.
//
// Tolerances, in cage diameters: 1e-5 from float coordinates (the CPU multiplies in float, this in double),
// 1e-9 from double coordinates.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "deform/deformer.h"
#include "deform/frame_point_kernel.h"
#include "frame_cases.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr int kLanes = 32;

template <typename Scalar, int Dim>
Eigen::MatrixXd framePortable(const CoordinateMatrix<Scalar>& C, const FrameCoordinates& frame, const FrameWeights& W) {
  const RowMatrixXd main = W.main, tail = W.tail;
  PortableFrameWeights weights{main.data(), tail.data(), frame.columns(), frame.mainColumns, W.mainOffset,
                               W.outputs,   {0, 0, 0},       W.finish};
  for (int a = 0; a < Dim && a < W.origin.size(); ++a) weights.origin[a] = W.origin(a);
  Eigen::MatrixXd out(C.rows(), Dim);
  for (int p = 0; p < C.rows(); ++p) {
    double y[kPortableMaxOutputs] = {0};
    for (int lane = 0; lane < kLanes; ++lane) {
      if (frame.isSparse())  // the sparse kernel's sums (Phong's rows, coordinate_layout.h)
        addSparseFramePartialSums(C.row(p).data(), frame.entryColumns.row(p).data(), static_cast<int>(C.cols()),
                                  weights, lane, kLanes, y);
      else
        addFramePartialSums(C.row(p).data(), weights, lane, kLanes, y);
    }
    double point[Dim];
    finishFramePoint<Dim>(y, W.finish, weights.origin, point);
    for (int a = 0; a < Dim; ++a) out(p, a) = point[a];
  }
  blendExteriorPoints(frame.exteriorBlends, out);
  return out;
}

template <int Dim>
Eigen::MatrixXd framePortable(const FrameCoordinates& frame, const FrameWeights& W) {
  return frame.isFloat() ? framePortable<float, Dim>(frame.floats, frame, W)
                         : framePortable<double, Dim>(frame.doubles, frame, W);
}

void expectPortableFramesMatch(const Cage& cage, const Eigen::MatrixXd& points) {
  test::expectFramesMatchCpu(cage, points, [&](const CageDeformer& deformer, const FrameWeights& W) {
    return cage.dim() == 3 ? framePortable<3>(deformer.frameCoordinates(), W)
                           : framePortable<2>(deformer.frameCoordinates(), W);
  });
}

TEST(CudaPortableFrame, MatchesCpuFrame3D) {
  const Cage cage = test::makeBumpySphere(1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-0.4, 0.4);
  Eigen::MatrixXd points(300, 3);
  for (int p = 0; p < points.rows(); ++p) points.row(p) << unit(rng), unit(rng), unit(rng);
  points.row(0) << 2.5, 0.1, -0.2;  // outside: its exterior rows are blended like on the CPU
  expectPortableFramesMatch(cage, points);
}

TEST(CudaPortableFrame, MatchesCpuFrame2D) {
  const Cage cage = makePolygonCage(test::lLoop());
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  Eigen::MatrixXd points(200, 2);
  for (int p = 0; p < points.rows(); ++p) points.row(p) << unit(rng), unit(rng);
  expectPortableFramesMatch(cage, points);
}

}  // namespace
}  // namespace somicage

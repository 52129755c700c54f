// The per-point finish of a frame (o + T^-1 b, Eq. 11) that the CPU and CUDA kernels share: exact where T is
// invertible, finite and least-squares where it is singular.
#include "deform/frame_point_kernel.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <array>

#include "deform/frame_evaluation.h"

namespace somicage {
namespace {

// The 12 outputs of a 3D frame point for T and b (layout in frame_evaluation.h).
std::array<double, 12> outputs3(const Eigen::Matrix3d& T, const Eigen::Vector3d& b) {
  std::array<double, 12> y{};
  const Eigen::VectorXd t = tOutputsFromMatrix(T);
  for (int k = 0; k < 9; ++k) y[k] = t(k);
  for (int a = 0; a < 3; ++a) y[9 + a] = b(a);
  return y;
}

TEST(FramePointKernel, InvertibleTIsSolvedAboutTheOrigin) {
  Eigen::Matrix3d T;
  T << 2, 0.3, -0.1, -0.2, 1.5, 0.4, 0.1, -0.3, 0.8;
  const Eigen::Vector3d b(0.7, -1.1, 2.3), o(10, 20, 30);
  const auto y = outputs3(T, b);
  double x[3];
  finishFramePoint<3>(y.data(), FrameFinish::SolveT, o.data(), x);
  EXPECT_LE((Eigen::Map<Eigen::Vector3d>(x) - (o + T.inverse() * b)).norm(), 1e-14);
}

TEST(FramePointKernel, SingularTGivesTheLeastSquaresPointNotNaN) {
  const Eigen::Vector3d o(-5, 1, 2);
  double x[3];
  // Rank 2 with b in its range: the solution along the null direction is 0, i.e. the point stays at o there.
  const auto rank2 = outputs3(Eigen::Vector3d(2, 4, 0).asDiagonal(), Eigen::Vector3d(1, 2, 0));
  finishFramePoint<3>(rank2.data(), FrameFinish::SolveT, o.data(), x);
  EXPECT_LE((Eigen::Map<Eigen::Vector3d>(x) - (o + Eigen::Vector3d(0.5, 0.5, 0))).norm(), 1e-10);
  // T = 0 (every rotation cancelled, or no integrals): the origin itself.
  const auto zero = outputs3(Eigen::Matrix3d::Zero(), Eigen::Vector3d(1, 1, 1));
  finishFramePoint<3>(zero.data(), FrameFinish::SolveT, o.data(), x);
  EXPECT_EQ(Eigen::Map<Eigen::Vector3d>(x), o);
  // 2D, rank 1.
  const double y2[6] = {3, 0, 0, 0, 6, 0};  // T = diag(3, 0), b = (6, 0)
  const double o2[3] = {1, 1, 0};
  double x2[2];
  finishFramePoint<2>(y2, FrameFinish::SolveT, o2, x2);
  EXPECT_NEAR(x2[0], 3, 1e-10);
  EXPECT_EQ(x2[1], 1);
}

}  // namespace
}  // namespace somicage

// The frames that every other frame backend (the CUDA kernel's host port, the CUDA device) is held to against the
// CPU frame: each method, float and double storage, global, local and blended rotations, on a bent cage.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "deformer.h"
#include "methods/method_descriptors.h"

namespace somicage::test {

// A smooth bend (and in 3D a twist) of the cage.
inline Eigen::MatrixXd bentCage(const Cage& cage) {
  Eigen::MatrixXd posed = cage.vertices;
  for (int i = 0; i < posed.rows(); ++i) {
    const double x = cage.vertices(i, 0);
    posed(i, 1) += 0.3 * x * x;
    if (cage.dim() == 3) posed(i, 2) += 0.2 * std::sin(2 * x) * cage.vertices(i, 1);
  }
  return posed;
}

// Evaluates every case with `frame` (the backend under test: the deformer's coordinates and one frame's weights
// in, #P by d points out) and expects the CPU's points within 1e-5 (float storage) or 1e-9 (double) diameters.
inline void expectFramesMatchCpu(
    const Cage& cage, const Eigen::MatrixXd& points,
    const std::function<Eigen::MatrixXd(const CageDeformer&, const FrameWeights&)>& frame) {
  struct Case {
    Method method;
    bool floatStorage;
    double blend;
  };
  const double diameter = cageDiameter(cage.vertices);
  const Eigen::MatrixXd posed = bentCage(cage);
  for (const Case& c : std::vector<Case>{{methods::somigliana(), true, 0.0},
                                         {methods::somigliana(), true, 1.0},
                                         {methods::somigliana(), true, 0.4},
                                         {methods::somigliana(), false, 0.0},
                                         {methods::somigliana(), false, 0.5},
                                         {methods::green(), true, 0.0},
                                         {methods::mvc(), false, 0.0}}) {
    PrecomputeOptions options;
    options.floatStorage = c.floatStorage;
    const auto deformer = makeDeformer(c.method, cage, points, options);
    const DeformParams params{c.blend, 0.3, 0.5, true};
    const Eigen::MatrixXd cpu = deformer->deform(posed, params);
    const Eigen::MatrixXd other = frame(*deformer, deformer->frameWeights(posed, params));
    ASSERT_EQ(other.rows(), cpu.rows());
    ASSERT_EQ(other.cols(), cpu.cols());
    const double error = (other - cpu).cwiseAbs().maxCoeff() / diameter;
    EXPECT_LE(error, c.floatStorage ? 1e-5 : 1e-9)
        << methodName(c.method) << (c.floatStorage ? " float" : " double") << " blend " << c.blend << " in "
        << cage.dim() << "D: largest difference " << error << " cage diameters";
  }
}

}  // namespace somicage::test

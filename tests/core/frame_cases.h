// The frames that every other frame backend (the CUDA kernel's host port, the CUDA device) is held to against the
// CPU frame: each method, float and double storage, global, local and blended rotations and the affine and stable
// variants, on a bent cage.
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
    VariantKind kind;
  };
  const double diameter = cageDiameter(cage.vertices);
  const Eigen::MatrixXd posed = bentCage(cage);
  const VariantKind paper = VariantKind::Blend;
  // The affine variant reads the tail's 18 affine terms (W.tail rows the other variants leave 0); the stable one
  // adds a global-frame traction to every face row (issue 26).
  for (const Case& c : std::vector<Case>{{methods::somigliana(), true, 0.0, paper},
                                         {methods::somigliana(), true, 1.0, paper},
                                         {methods::somigliana(), true, 0.4, paper},
                                         {methods::somigliana(), false, 0.0, paper},
                                         {methods::somigliana(), false, 0.5, paper},
                                         {methods::somigliana(), true, 0.0, VariantKind::Affine},
                                         {methods::somigliana(), false, 0.0, VariantKind::Affine},
                                         {methods::somigliana(), false, 1.0, VariantKind::Stable},
                                         {methods::green(), true, 0.0, paper},
                                         {methods::mvc(), false, 0.0, paper}}) {
    PrecomputeOptions options;
    options.floatStorage = c.floatStorage;
    const auto deformer = makeDeformer(c.method, cage, points, options);
    DeformParams params{c.blend, 0.3, 0.5, true};
    params.kind = c.kind;
    const Eigen::MatrixXd cpu = deformer->deform(posed, params);
    const Eigen::MatrixXd other = frame(*deformer, deformer->frameWeights(posed, params));
    ASSERT_EQ(other.rows(), cpu.rows());
    ASSERT_EQ(other.cols(), cpu.cols());
    const double error = (other - cpu).cwiseAbs().maxCoeff() / diameter;
    EXPECT_LE(error, c.floatStorage ? 1e-5 : 1e-9)
        << methodName(c.method) << (c.floatStorage ? " float" : " double") << " blend " << c.blend << " kind "
        << static_cast<int>(c.kind) << " in "
        << cage.dim() << "D: largest difference " << error << " cage diameters";
  }
}

}  // namespace somicage::test

// The frames that every other frame backend (the CUDA kernel's host port, the CUDA device) is held to against the
// CPU frame: each method, float and double storage, global, local and blended rotations and the affine and stable
// variants, on a bent cage.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "deform/deformer.h"

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
  // Every method of the registry in float and double; the methods with variants (those that read the blend) at
  // global, local and blended rotations, and the affine variant, which reads the tail's 18 affine terms (W.tail rows
  // the other variants leave 0), and the stable one, which adds a global-frame traction to every face row (issue 26).
  std::vector<Case> cases;
  for (Method m : allMethods()) {
    cases.push_back({m, true, 0.0, paper});
    cases.push_back({m, false, 0.0, paper});
    if (readsParameter(m, kParamBlend))
      cases.insert(cases.end(), {{m, true, 1.0, paper},
                                 {m, true, 0.4, paper},
                                 {m, false, 0.5, paper},
                                 {m, true, 0.0, VariantKind::Affine},
                                 {m, false, 0.0, VariantKind::Affine},
                                 {m, false, 1.0, VariantKind::Stable}});
  }
  for (const Case& c : cases) {
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

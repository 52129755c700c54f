// The frame devices (core/deform/frame_evaluator.h): the CPU evaluator and the OpenGL one (render/gl_frame_evaluator.h)
// against an independent evaluation of the frame from C and W written here from frame_evaluation.h's definition
// (y_p = C_p W, then o + T_p^-1 b_p for the d^2 + d outputs of Somigliana), on a bent cube pose that is not a
// similarity, for Somigliana (local, Eq. 11 with the per-point solve) and mean value coordinates (y_p itself).
// The CPU holds it to 1e-12 of the cage diameter (double C), OpenGL to 1e-5 (float C and float sums, as the
// editor's GPU deformer). Needs an OpenGL 4.3 context (ctest runs this binary under xvfb-run); the OpenGL half
// skips visibly without one.
#include "deform/frame_evaluator.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>

#include "core/test_shapes.h"
#include "deform/deformer.h"
#include "gl_frame_evaluator.h"
#include "methods/method_descriptors.h"

namespace somicage {
namespace {

// Every point of C evaluated by plain loops (interior points only: no exterior rows to blend).
Eigen::MatrixXd independentFrame(const FrameCoordinates& C, const FrameWeights& W, int d) {
  EXPECT_TRUE(C.exteriorBlends.empty());
  Eigen::MatrixXd out(C.numPoints(), d);
  for (int p = 0; p < C.numPoints(); ++p) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(W.outputs);
    // Stored entry e of the row is column k of C: e itself (dense), or its entryColumns (sparse rows: Phong).
    for (int e = 0; e < C.storedColumns(); ++e) {
      const double c = C.isFloat() ? C.floats(p, e) : C.doubles(p, e);
      const int k = C.isSparse() ? C.entryColumns(p, e) : e;
      for (int j = 0; j < W.outputs; ++j) {
        if (k < C.mainColumns && j >= W.mainOffset) y(j) += c * W.main(k, j - W.mainOffset);
        if (k >= C.mainColumns) y(j) += c * W.tail(k - C.mainColumns, j);
      }
    }
    if (W.finish == FrameFinish::Linear) {
      out.row(p) = y.transpose();
      continue;
    }
    // 3D: S = (xx, yy, zz, xy, xz, yz), A w = omega x w with omega = y[6..8], b = y[9..11].
    EXPECT_EQ(d, 3);
    Eigen::Matrix3d T;
    T << y(0), y(3), y(4), y(3), y(1), y(5), y(4), y(5), y(2);
    T += (Eigen::Matrix3d() << 0, -y(8), y(7), y(8), 0, -y(6), -y(7), y(6), 0).finished();
    const Eigen::Vector3d b = y.segment<3>(9);
    const Eigen::Vector3d origin = W.origin.size() == 3 ? Eigen::Vector3d(W.origin) : Eigen::Vector3d::Zero();
    out.row(p) = (origin + T.partialPivLu().solve(b)).transpose();
  }
  return out;
}

struct Case {
  std::string name;
  Method method;
  DeformParams params;
};

class FrameEvaluatorTest : public ::testing::TestWithParam<Case> {};

TEST_P(FrameEvaluatorTest, CpuAndOpenGlMatchAnIndependentFrameSum) {
  const Cage cage = test::makeCube();
  const Eigen::MatrixXd points = test::randomBoxPoints(40, 3, -0.8, 0.8, 7);
  const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.3, 11);
  const double diameter = 2 * std::sqrt(3.0);
  const std::unique_ptr<CageDeformer> deformer = makeDeformer(GetParam().method, cage, points, {});
  ASSERT_TRUE(deformer->diagnostics().exteriorCount() == 0);
  const FrameWeights W = deformer->frameWeights(posed, GetParam().params);
  const Eigen::MatrixXd expected = independentFrame(deformer->frameCoordinates(), W, 3);
  ASSERT_GT((expected - points).cwiseAbs().maxCoeff(), 1e-2) << "the pose must move the points";

  Eigen::MatrixXd cpu;
  cpuFrameDevice().make(*deformer)->evaluate(W, cpu);
  ASSERT_EQ(cpu.rows(), points.rows());
  EXPECT_LE((cpu - expected).rowwise().norm().maxCoeff(), 1e-12 * diameter);

  std::unique_ptr<FrameEvaluator> gl;
  try {
    gl = render::openGlFrameDevice().make(*deformer);
  } catch (const FrameDeviceUnavailable& e) {
    GTEST_SKIP() << "OpenGL frame device: " << e.what();
  }
  Eigen::MatrixXd gpu;
  gl->evaluate(W, gpu);
  ASSERT_EQ(gpu.rows(), points.rows());
  ASSERT_EQ(gpu.cols(), 3);
  EXPECT_LE((gpu - expected).rowwise().norm().maxCoeff(), 1e-5 * diameter);
  EXPECT_LE((gpu - cpu).rowwise().norm().maxCoeff(), 1e-5 * diameter);
}

// Every method of the registry; those with variants (that read the blend) at the global and local one.
std::vector<Case> registryCases() {
  std::vector<Case> cases;
  for (Method m : allMethods()) {
    if (!readsParameter(m, kParamBlend)) {
      cases.push_back({m->name, m, {}});
      continue;
    }
    cases.push_back({methodName(m) + "_local", m, {1.0, 0.3, 1.0, true}});
    cases.push_back({methodName(m) + "_global", m, {0.0, 0.2, 0.5, true}});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Methods, FrameEvaluatorTest, ::testing::ValuesIn(registryCases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

TEST(FrameDevices, FindsByName) {
  const FrameDevices devices = {cpuFrameDevice(), render::openGlFrameDevice()};
  ASSERT_NE(findFrameDevice(devices, "opengl"), nullptr);
  EXPECT_EQ(findFrameDevice(devices, "opengl")->benchKey, "gpu");
  EXPECT_EQ(findFrameDevice(devices, "cuda"), nullptr);
}

}  // namespace
}  // namespace somicage

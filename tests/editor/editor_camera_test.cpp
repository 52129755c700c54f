// OrbitCamera: projection consistency, framing, orbit/pan/zoom. Tolerances are relative to the scene size.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "interaction/camera.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// Screen position through the GL matrices, for comparison with OrbitCamera::project.
Eigen::Vector2d viaMatrices(const OrbitCamera& c, const Eigen::Vector3d& p, double w, double h) {
  const Eigen::Vector4d clip = c.projectionMatrix(w / h) * c.viewMatrix() * p.homogeneous();
  const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
  return {0.5 * (ndc.x() + 1.0) * w, 0.5 * (1.0 - ndc.y()) * h};
}

}  // namespace

TEST(EditorCamera, BasisIsOrthonormalAndRightHanded) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d(1, 2, 3), 4.0, 0.7, -0.4});
  EXPECT_NEAR(c.right().dot(c.up()), 0.0, 1e-12);
  EXPECT_NEAR(c.right().dot(c.forward()), 0.0, 1e-12);
  EXPECT_NEAR(c.up().norm(), 1.0, 1e-12);
  EXPECT_LT((c.right().cross(c.up()) + c.forward()).norm(), 1e-12);  // right x up = towards the viewer
  EXPECT_NEAR((c.eye() - c.state().target).norm(), 4.0, 1e-12);
}

TEST(EditorCamera, ProjectMatchesMatricesIn3DAnd2D) {
  for (bool twoD : {false, true}) {
    OrbitCamera c;
    c.setMode2D(twoD);
    c.setState({Eigen::Vector3d(0.3, -0.2, 0.1), 6.0, 0.5, 0.3});
    for (const Eigen::Vector3d& p :
         {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0.5, -0.7), Eigen::Vector3d(-1, 1, 1)}) {
      Eigen::Vector2d s;
      ASSERT_TRUE(c.project(p, 800, 600, s));
      EXPECT_LT((s - viaMatrices(c, p, 800, 600)).norm(), 1e-6) << "2D=" << twoD;
    }
  }
}

TEST(EditorCamera, UnprojectInvertsProject) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d(0, 0, 0), 5.0, 1.1, 0.2});
  const Eigen::Vector3d p(0.4, -0.3, 0.9);
  Eigen::Vector2d s;
  double depth = 0;
  ASSERT_TRUE(c.project(p, 1024, 768, s, &depth));
  EXPECT_LT((c.unproject(s, depth, 1024, 768) - p).norm(), 1e-10);
}

TEST(EditorCamera, TargetProjectsToViewportCentre) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d(2, 3, 4), 7.0, -0.3, 0.9});
  Eigen::Vector2d s;
  ASSERT_TRUE(c.project(c.state().target, 640, 480, s));
  EXPECT_LT((s - Eigen::Vector2d(320, 240)).norm(), 1e-9);
}

TEST(EditorCamera, PointsBehindTheEyeAreNotProjected) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d::Zero(), 2.0, 0.0, 0.0});  // eye at z = 2 looking down -z
  Eigen::Vector2d s;
  EXPECT_FALSE(c.project(Eigen::Vector3d(0, 0, 5), 100, 100, s));
}

TEST(EditorCamera, FrameFitsTheBoxForAnyAspect) {
  const Eigen::Vector3d lo(-2, -0.5, -0.5), hi(2, 0.5, 0.5);
  for (bool twoD : {false, true}) {
    for (double aspect : {0.4, 1.0, 2.5}) {
      OrbitCamera c;
      c.setMode2D(twoD);
      c.frame(lo, hi, aspect);
      const double h = 500, w = h * aspect;
      for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d corner((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z());
        Eigen::Vector2d s;
        ASSERT_TRUE(c.project(corner, w, h, s));
        EXPECT_GE(s.x(), 0.0) << "aspect " << aspect << " 2D " << twoD;
        EXPECT_LE(s.x(), w);
        EXPECT_GE(s.y(), 0.0);
        EXPECT_LE(s.y(), h);
      }
    }
  }
}

TEST(EditorCamera, PanKeepsTheTargetDepthPointUnderTheCursor) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d(0, 0, 0), 5.0, 0.4, 0.3});
  const Eigen::Vector3d p(0, 0, 0);  // at the target's depth
  Eigen::Vector2d before, after;
  c.project(p, 800, 600, before);
  c.pan(37, -12, 600);
  c.project(p, 800, 600, after);
  EXPECT_LT((after - before - Eigen::Vector2d(37, -12)).norm(), 1e-6);
}

TEST(EditorCamera, OrbitKeepsTargetAndDistanceAndClampsPitch) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d(1, 1, 1), 3.0, 0.0, 0.0});
  c.orbit(120, 10000);
  EXPECT_LT((c.state().target - Eigen::Vector3d(1, 1, 1)).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(c.state().distance, 3.0);
  EXPECT_LE(c.state().pitch, OrbitCamera::kMaxPitch);
}

TEST(EditorCamera, ZoomIsMultiplicativeAndReversible) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d::Zero(), 4.0, 0, 0});
  c.zoom(3);
  EXPECT_LT(c.state().distance, 4.0);
  c.zoom(-3);
  EXPECT_NEAR(c.state().distance, 4.0, 1e-12);
}

TEST(EditorCamera, Mode2DDoesNotOrbitAndIsOrthographic) {
  OrbitCamera c;
  c.setMode2D(true);
  c.orbit(100, 100);
  EXPECT_EQ(c.state().yaw, 0.0);
  EXPECT_EQ(c.state().pitch, 0.0);
  EXPECT_EQ(c.projectionMatrix(1.5)(3, 2), 0.0);  // no perspective divide
  // Orthographic: screen position does not depend on z.
  Eigen::Vector2d a, b;
  c.project(Eigen::Vector3d(0.5, 0.2, 0.0), 400, 300, a);
  c.project(Eigen::Vector3d(0.5, 0.2, -1.0), 400, 300, b);
  EXPECT_LT((a - b).norm(), 1e-9);
}

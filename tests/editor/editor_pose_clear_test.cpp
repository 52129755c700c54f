// Alt+G / Alt+R / Alt+S (pose_clear.h) against poses made from the rest pose by a known translation, rotation or
// stretch: clearing that part gives the rest positions back (1e-12), and leaves the other parts.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "model/pose_clear.h"
#include "model/scene.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

const std::vector<int> kSelected{0, 1, 2, 3, 4, 5};

// The selected rows of rest mapped by x -> c + M (x - c) + t, c = their rest centroid.
Eigen::MatrixXd mapped(const Eigen::MatrixXd& rest, const Eigen::Matrix3d& m, const Eigen::Vector3d& t) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i : kSelected) c += rest.row(i).transpose();
  c /= static_cast<double>(kSelected.size());
  Eigen::MatrixXd out = rest;
  for (int i : kSelected) out.row(i) = (c + m * (rest.row(i).transpose() - c) + t).transpose();
  return out;
}

double maxDiff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff(); }

}  // namespace

TEST(EditorPoseClear, EachClearUndoesItsOwnPart) {
  const Eigen::MatrixXd rest = makeDemoScene(3).restCage.vertices;
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix3d q = Eigen::AngleAxisd(-0.4, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  const Eigen::Matrix3d stretch = q * Eigen::Vector3d(2.0, 0.5, 1.5).asDiagonal() * q.transpose();  // symmetric
  const Eigen::Vector3d t(0.3, -0.2, 0.5);

  EXPECT_LT(
      maxDiff(clearTransform(ClearKind::Location, rest, mapped(rest, Eigen::Matrix3d::Identity(), t), kSelected), rest),
      1e-12);
  EXPECT_LT(
      maxDiff(clearTransform(ClearKind::Rotation, rest, mapped(rest, r, Eigen::Vector3d::Zero()), kSelected), rest),
      1e-12);
  EXPECT_LT(
      maxDiff(clearTransform(ClearKind::Scale, rest, mapped(rest, stretch, Eigen::Vector3d::Zero()), kSelected), rest),
      1e-12);

  // Rotation and stretch together (A = R S): clearing the scale leaves the pure rotation, clearing the rotation
  // the pure stretch; the location stays.
  const Eigen::MatrixXd both = mapped(rest, r * stretch, t);
  EXPECT_LT(maxDiff(clearTransform(ClearKind::Scale, rest, both, kSelected), mapped(rest, r, t)), 1e-12);
  EXPECT_LT(maxDiff(clearTransform(ClearKind::Rotation, rest, both, kSelected), mapped(rest, stretch, t)), 1e-12);
  // Unselected handles never move.
  const Eigen::MatrixXd cleared = clearTransform(ClearKind::Location, rest, both, kSelected);
  for (Eigen::Index i = 6; i < rest.rows(); ++i) EXPECT_EQ(cleared.row(i), both.row(i));
}

TEST(EditorPoseClear, OneHandleHasLocationOnlyAnd2DWorks) {
  const Eigen::MatrixXd rest = makeDemoScene(2).restCage.vertices;
  Eigen::MatrixXd pose = rest;
  pose.row(2) += Eigen::RowVector2d(0.5, 0.25);
  EXPECT_EQ(clearTransform(ClearKind::Rotation, rest, pose, {2}), pose);
  EXPECT_EQ(clearTransform(ClearKind::Location, rest, pose, {2}), rest);
  const std::vector<int> all{0, 1, 2, 3};
  Eigen::MatrixXd turned = rest;
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(1.0).toRotationMatrix();
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (int i : all) c += rest.row(i).transpose() / 4.0;
  for (int i : all) turned.row(i) = (c + r * (rest.row(i).transpose() - c)).transpose();
  EXPECT_LT(maxDiff(clearTransform(ClearKind::Rotation, rest, turned, all), rest), 1e-12);
}

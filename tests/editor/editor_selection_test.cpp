// Picking, box selection and the Selection set.
#include <gtest/gtest.h>

#include "model/selection.h"

using namespace somicage;
using namespace somicage::editor;

namespace {
ScreenPoint sp(double x, double y, double depth, bool visible = true) {
  ScreenPoint p;
  p.position = Eigen::Vector2d(x, y);
  p.depth = depth;
  p.visible = visible;
  return p;
}
}  // namespace

TEST(EditorPicking, NearestWithinRadius) {
  const std::vector<ScreenPoint> pts = {sp(10, 10, 1), sp(50, 50, 1), sp(54, 50, 1)};
  EXPECT_EQ(pickPoint(pts, Eigen::Vector2d(53.5, 50), 10), 2);
  EXPECT_EQ(pickPoint(pts, Eigen::Vector2d(12, 9), 10), 0);
  EXPECT_EQ(pickPoint(pts, Eigen::Vector2d(200, 200), 10), -1);
}

TEST(EditorPicking, OverlappingHandlesPreferTheNearerOne) {
  const std::vector<ScreenPoint> pts = {sp(50, 50, 5.0), sp(50.2, 50, 2.0)};
  EXPECT_EQ(pickPoint(pts, Eigen::Vector2d(50, 50), 10), 1);
}

TEST(EditorPicking, HiddenPointsAreNeverPicked) {
  const std::vector<ScreenPoint> pts = {sp(50, 50, 1, false)};
  EXPECT_EQ(pickPoint(pts, Eigen::Vector2d(50, 50), 10), -1);
  EXPECT_TRUE(pointsInRect(pts, Eigen::Vector2d(0, 0), Eigen::Vector2d(100, 100)).empty());
}

TEST(EditorPicking, ProjectPointsOfACageFromTheCamera) {
  OrbitCamera c;
  c.setState({Eigen::Vector3d::Zero(), 5.0, 0.0, 0.0});
  Eigen::MatrixXd v(2, 3);
  v << 0, 0, 0, 1, 0, 0;
  const std::vector<ScreenPoint> pts = projectPoints(c, v, 800, 600);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_NEAR(pts[0].position.x(), 400, 1e-9);
  EXPECT_GT(pts[1].position.x(), 400);  // +x is to the right
  EXPECT_EQ(pickPoint(pts, pts[1].position, 3), 1);
}

TEST(EditorBoxSelection, CornersInAnyOrderAndInclusive) {
  const std::vector<ScreenPoint> pts = {sp(10, 10, 1), sp(20, 20, 1), sp(30, 5, 1), sp(20, 30, 1)};
  const std::vector<int> a = pointsInRect(pts, Eigen::Vector2d(5, 5), Eigen::Vector2d(20, 20));
  const std::vector<int> b = pointsInRect(pts, Eigen::Vector2d(20, 5), Eigen::Vector2d(5, 20));
  EXPECT_EQ(a, (std::vector<int>{0, 1}));
  EXPECT_EQ(a, b);
}

TEST(EditorSelection, ClickModes) {
  Selection s;
  s.resize(5);
  s.click(2, Selection::Mode::Replace);
  EXPECT_EQ(s.indices(), (std::vector<int>{2}));
  s.click(4, Selection::Mode::Toggle);
  EXPECT_EQ(s.indices(), (std::vector<int>{2, 4}));
  s.click(2, Selection::Mode::Toggle);
  EXPECT_EQ(s.indices(), (std::vector<int>{4}));
  s.click(-1, Selection::Mode::Replace);  // click on nothing clears
  EXPECT_TRUE(s.empty());
  s.click(99, Selection::Mode::Add);  // out of range is ignored
  EXPECT_TRUE(s.empty());
}

TEST(EditorSelection, BoxModesAllAndNone) {
  Selection s;
  s.resize(6);
  s.apply({1, 2}, Selection::Mode::Replace);
  s.apply({2, 3}, Selection::Mode::Add);
  EXPECT_EQ(s.indices(), (std::vector<int>{1, 2, 3}));
  s.apply({1, 5}, Selection::Mode::Toggle);
  EXPECT_EQ(s.indices(), (std::vector<int>{2, 3, 5}));
  s.apply({0}, Selection::Mode::Replace);
  EXPECT_EQ(s.indices(), (std::vector<int>{0}));
  s.selectAll();
  EXPECT_EQ(s.count(), 6);
  s.clear();
  EXPECT_EQ(s.count(), 0);
}

TEST(EditorSelection, Centroid) {
  Selection s;
  s.resize(3);
  Eigen::MatrixXd v(3, 2);
  v << 0, 0, 2, 0, 2, 4;
  s.apply({1, 2}, Selection::Mode::Replace);
  EXPECT_LT((s.centroid(v) - Eigen::Vector2d(2, 2)).norm(), 1e-12);
}

// Vertex / edge / face picking (element_pick.h) on hand-placed screen points: two triangles of a square, the
// second one nearer in depth and overlapping the first on screen.
#include <gtest/gtest.h>

#include <algorithm>

#include "interaction/element_pick.h"

using namespace somicage::editor;

namespace {

std::vector<ScreenPoint> points(const std::vector<Eigen::Vector3d>& xyDepth) {
  std::vector<ScreenPoint> pts;
  for (const Eigen::Vector3d& p : xyDepth) pts.push_back({p.head<2>(), p.z(), true});
  return pts;
}

}  // namespace

TEST(EditorElementPick, EdgesAndFacesSelectTheirVertices) {
  // A square 0 (0,0) 1 (100,0) 2 (100,100) 3 (0,100) as triangles 012 and 023, and a triangle 4 5 6 in front
  // covering the square's centre.
  const std::vector<ScreenPoint> pts =
      points({{0, 0, 5}, {100, 0, 5}, {100, 100, 5}, {0, 100, 5}, {40, 40, 1}, {80, 40, 1}, {40, 80, 1}});
  Eigen::MatrixXi faces(3, 3);
  faces << 0, 1, 2, 0, 2, 3, 4, 5, 6;
  EXPECT_EQ(cageEdges(faces).size(), 8u);  // 5 of the square (its diagonal once) + 3
  EXPECT_EQ(pickElement(ElementMode::Vertex, pts, faces, {3, 2}, 10), (std::vector<int>{0}));
  EXPECT_EQ(pickElement(ElementMode::Edge, pts, faces, {50, 3}, 10), (std::vector<int>{0, 1}));
  EXPECT_EQ(pickElement(ElementMode::Edge, pts, faces, {30, 30}, 5), (std::vector<int>{0, 2}));  // the diagonal
  EXPECT_EQ(pickElement(ElementMode::Face, pts, faces, {90, 10}, 10), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(pickElement(ElementMode::Face, pts, faces, {10, 90}, 10), (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(pickElement(ElementMode::Face, pts, faces, {45, 50}, 10), (std::vector<int>{4, 5, 6}));  // the nearer
  EXPECT_TRUE(pickElement(ElementMode::Face, pts, faces, {150, 50}, 10).empty());
  EXPECT_TRUE(pickElement(ElementMode::Edge, pts, faces, {150, 50}, 10).empty());
  // 2D cages: faces are segments, and pick like edges.
  Eigen::MatrixXi segments(4, 2);
  segments << 0, 1, 1, 2, 2, 3, 3, 0;
  EXPECT_EQ(pickElement(ElementMode::Face, pts, segments, {98, 50}, 10), (std::vector<int>{1, 2}));
}

TEST(EditorElementPick, TheSelectedEdgesAreThoseWithBothVerticesSelected) {
  // Issue 24, row 15: a selected edge was not highlighted. Triangles 012 and 023 of a square: selecting 0 and 2
  // (the diagonal) highlights only the diagonal; a face's three vertices highlight its three edges.
  Eigen::MatrixXi faces(2, 3);
  faces << 0, 1, 2, 0, 2, 3;
  using Edges = std::vector<std::pair<int, int>>;
  EXPECT_EQ(selectedEdges(faces, {true, false, true, false}), (Edges{{0, 2}}));
  Edges face = selectedEdges(faces, {true, true, true, false});
  std::sort(face.begin(), face.end());
  EXPECT_EQ(face, (Edges{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_TRUE(selectedEdges(faces, {true, false, false, false}).empty());
  EXPECT_TRUE(selectedEdges(faces, {}).empty());  // no flags yet
}

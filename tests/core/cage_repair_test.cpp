// Cage repair: faces reversed at random come back exactly as they were, inside-out components are turned outward,
// cavities stay or become inward, clockwise polygons are reversed, and what cannot be repaired is left as it is.
// Vertices never change.
#include "cage/cage_repair.h"

#include <gtest/gtest.h>

#include <random>

#include "cage/cage_validation.h"
#include "test_models.h"
#include "test_shapes.h"

namespace somicage {
namespace {

Cage reversed(Cage cage, const std::vector<int>& faces) {
  for (const int j : faces) cage.faces.row(j) = cage.faces.row(j).reverse().eval();
  return cage;
}

Cage allReversed(const Cage& cage) {
  std::vector<int> all(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j) all[j] = j;
  return reversed(cage, all);
}

// Two cages side by side in one: b's vertices and faces follow a's.
Cage merged(const Cage& a, const Cage& b) {
  Cage both;
  both.vertices.resize(a.numVertices() + b.numVertices(), a.dim());
  both.vertices << a.vertices, b.vertices;
  both.faces.resize(a.numFaces() + b.numFaces(), a.faces.cols());
  both.faces << a.faces, b.faces.array() + a.numVertices();
  return both;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& line : lines) all += "\n  " + line;
  return all;
}

TEST(CageRepair, ValidCageIsUnchanged) {
  const Cage cube = test::makeCube();
  const CageRepair repair = repairCage(cube);
  EXPECT_TRUE(repair.fixes.empty()) << joined(repair.fixes);
  EXPECT_EQ(repair.cage.faces, cube.faces);
  EXPECT_EQ(repair.cage.vertices, cube.vertices);
}

TEST(CageRepair, FlippedFacesMatchTheirNeighboursAgain) {
  const Cage cube = test::makeCube();
  const CageRepair repair = repairCage(reversed(cube, {1, 4, 7}));
  EXPECT_EQ(repair.cage.faces, cube.faces);
  EXPECT_EQ(repair.cage.vertices, cube.vertices);
  ASSERT_EQ(repair.fixes.size(), 1u) << joined(repair.fixes);
  EXPECT_EQ(repair.fixes[0], "flipped 3 faces (1, 4, 7) to match their neighbours' orientation");
  EXPECT_TRUE(validateCage(repair.cage).valid());
}

TEST(CageRepair, MajorityOfFlippedFacesThenOutward) {
  // Seven of twelve faces reversed: the walk keeps the seven, then the cube points inward and is flipped whole.
  const Cage cube = test::makeCube();
  const CageRepair repair = repairCage(reversed(cube, {0, 1, 2, 3, 5, 8, 11}));
  EXPECT_EQ(repair.cage.faces, cube.faces);
  ASSERT_EQ(repair.fixes.size(), 2u) << joined(repair.fixes);
  EXPECT_EQ(repair.fixes[0], "flipped 5 faces (4, 6, 7, 9, 10) to match their neighbours' orientation");
  EXPECT_EQ(repair.fixes[1], "the cage's normals pointed inward (signed volume -8): flipped all 12 faces");
}

TEST(CageRepair, InsideOutCubeIsFlipped) {
  const Cage cube = test::makeCube();
  const CageRepair repair = repairCage(allReversed(cube));
  EXPECT_EQ(repair.cage.faces, cube.faces);
  ASSERT_EQ(repair.fixes.size(), 1u) << joined(repair.fixes);
  EXPECT_EQ(repair.fixes[0], "the cage's normals pointed inward (signed volume -8): flipped all 12 faces");
}

TEST(CageRepair, TwoComponentsAreRepairedIndependently) {
  const Cage cube = test::makeCube(), sphere = test::makeIcosphere(1);  // 12 and 80 faces, apart
  Cage apart = sphere;
  apart.vertices.col(0).array() += 5.0;
  const Cage original = merged(cube, apart);
  const Cage broken = merged(reversed(cube, {3}), allReversed(apart));
  const CageRepair repair = repairCage(broken);
  EXPECT_EQ(repair.cage.faces, original.faces);
  ASSERT_EQ(repair.fixes.size(), 2u) << joined(repair.fixes);
  EXPECT_EQ(repair.fixes[0], "flipped 1 face (3) to match its neighbours' orientation");
  EXPECT_NE(repair.fixes[1].find("faces 12, 13, 14, 15, 16 and 75 more"), std::string::npos) << repair.fixes[1];
  EXPECT_NE(repair.fixes[1].find("pointed inward: flipped its 80 faces"), std::string::npos) << repair.fixes[1];
  EXPECT_TRUE(validateCage(repair.cage).valid()) << joined(describeCageProblems(validateCage(repair.cage)));
}

TEST(CageRepair, CavityPointsIntoTheHole) {
  // A hollow cube: the outer cube points out, the inner one (the cavity) points into the hole, so that the
  // normals leave the solid everywhere. That is valid as it is; an outward cavity is flipped.
  const Cage outer = test::makeCube();
  Cage inner = test::makeCube();
  inner.vertices *= 0.5;
  const Cage hollow = merged(outer, allReversed(inner));
  CageRepair repair = repairCage(hollow);
  EXPECT_TRUE(repair.fixes.empty()) << joined(repair.fixes);
  EXPECT_EQ(repair.cage.faces, hollow.faces);

  repair = repairCage(merged(outer, inner));
  EXPECT_EQ(repair.cage.faces, hollow.faces);
  ASSERT_EQ(repair.fixes.size(), 1u) << joined(repair.fixes);
  EXPECT_NE(repair.fixes[0].find("it bounds a cavity"), std::string::npos) << repair.fixes[0];

  // A tetrahedron that crosses the cube's side is not a cavity, though most of it is inside: left outward.
  Cage spike = test::makeCube();
  spike.vertices.resize(4, 3);
  spike.vertices << 0.5, 0.5, -0.4, 0.5, 0.35, -0.32, 0.5, 0.35, -0.48, 1.5, 0.4, -0.4;
  spike.faces.resize(4, 3);
  spike.faces << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
  const Cage pierced = merged(outer, spike);
  repair = repairCage(pierced);
  EXPECT_TRUE(repair.fixes.empty()) << joined(repair.fixes);
  EXPECT_EQ(repair.cage.faces, pierced.faces);
}

TEST(CageRepair, ClockwisePolygonIsReversed) {
  Eigen::MatrixXd clockwise(4, 2);
  clockwise << -1, -1, -1, 1, 1, 1, 1, -1;
  const Cage square = makePolygonCage(clockwise);
  const CageRepair repair = repairCage(square);
  EXPECT_EQ(repair.cage.vertices, square.vertices);
  EXPECT_EQ(repair.cage.faces, square.faces.rowwise().reverse().eval());
  ASSERT_EQ(repair.fixes.size(), 1u) << joined(repair.fixes);
  EXPECT_EQ(repair.fixes[0], "the polygon was clockwise (signed area -4): reversed it (all 4 edges)");
  const CageReport report = validateCage(repair.cage);
  EXPECT_TRUE(report.valid()) << joined(describeCageProblems(report));
  EXPECT_DOUBLE_EQ(report.signedVolume, 4.0);
}

TEST(CageRepair, ReversedPolygonEdgeFollowsTheLoopAgain) {
  const Cage star = test::makeStarPolygon(5);
  const CageRepair repair = repairCage(reversed(star, {2}));
  EXPECT_EQ(repair.cage.faces, star.faces);
  ASSERT_EQ(repair.fixes.size(), 1u) << joined(repair.fixes);
  EXPECT_EQ(repair.fixes[0], "reversed 1 edge (2) to match its neighbours' orientation");
}

TEST(CageRepair, WhatCannotBeRepairedIsLeftAlone) {
  Cage open = reversed(test::makeCube(), {0});
  open.faces.conservativeResize(11, 3);  // a hole: no orientation is repaired
  CageRepair repair = repairCage(open);
  EXPECT_TRUE(repair.fixes.empty());
  EXPECT_EQ(repair.cage.faces, open.faces);

  Cage invalid = allReversed(test::makeCube());
  invalid.faces(4, 2) = 8;  // no such vertex
  repair = repairCage(invalid);
  EXPECT_TRUE(repair.fixes.empty());
  EXPECT_EQ(repair.cage.faces, invalid.faces);

  Cage fin = test::makeCube();  // an edge with four faces
  fin.faces.conservativeResize(14, 3);
  fin.faces.row(12) = fin.faces.row(0);
  fin.faces.row(13) << fin.faces(0, 0), fin.faces(0, 2), fin.faces(0, 1);
  repair = repairCage(fin);
  EXPECT_TRUE(repair.fixes.empty());
  EXPECT_EQ(repair.cage.faces, fin.faces);
}

// Every triangle cage of the shared models, its faces reversed at random (and sometimes all of them, so that the
// majority points inward), repairs to the published orientation.
class CageRepairModels : public ::testing::TestWithParam<test::ModelCase> {};

TEST_P(CageRepairModels, ScrambledOrientationComesBack) {
  const test::ModelCase& c = GetParam();
  if (test::skipIfModelAbsent(c)) return;
  const Cage cage = loadCage(test::modelPath(c, c.cage));
  ASSERT_TRUE(validateCage(cage).valid()) << c.cage << joined(describeCageProblems(validateCage(cage)));
  std::mt19937 random(11);
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<int> flipped;
    for (int j = 0; j < cage.numFaces(); ++j) {
      if (random() % (trial == 3 ? 8 : 2) != 0) flipped.push_back(j);  // trial 3: mostly reversed
    }
    const CageRepair repair = repairCage(reversed(cage, flipped));
    EXPECT_EQ(repair.cage.faces, cage.faces) << "trial " << trial;
    EXPECT_EQ(repair.cage.vertices, cage.vertices);
    EXPECT_FALSE(repair.fixes.empty());
  }
}

INSTANTIATE_TEST_SUITE_P(SharedModels, CageRepairModels, ::testing::ValuesIn(test::modelCases()), test::modelCaseName);

}  // namespace
}  // namespace somicage

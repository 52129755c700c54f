// Volume meshes of a cage (core/geometry/volume_mesh.cpp): what checkVolumeMesh accepts, repairs and refuses, and the
// star of a star-shaped cage.
#include "geometry/volume_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "base/errors.h"
#include "core/test_shapes.h"
#include "core/volume_mesh_checks.h"

namespace somicage {
namespace {

TEST(VolumeMesh, StarOfAStarShapedCageFillsIt) {
  for (const Cage& cage : {test::makeCube(), test::makeExtrudedL(), makePolygonCage(test::lLoop())}) {
    const std::unique_ptr<VolumeMesh> star = starVolumeMesh(cage);
    ASSERT_TRUE(star);
    EXPECT_EQ(star->numVertices(), cage.numVertices() + 1);
    EXPECT_NEAR(test::totalMeasure(*star), cage.dim() == 3 ? (cage.numVertices() == 8 ? 8.0 : 3.0) : 3.0, 1e-13);
    VolumeMesh copy = *star;
    EXPECT_EQ(checkVolumeMesh(copy, cage, {"star", {}, {}}), 0);
  }
}

// The cube's star: its 18 cage edges (12 sides, 6 face diagonals) and 8 spokes to the centre, each once; the
// L's polygon fan (2D): its 8 sides and 8 spokes.
TEST(VolumeMesh, EdgesAreTheCagesAndTheSpokesEachOnce) {
  const Cage cube = test::makeCube();
  const Eigen::MatrixXi edges = volumeMeshEdges(*starVolumeMesh(cube));
  ASSERT_EQ(edges.rows(), 26);
  std::set<std::pair<int, int>> expected;
  for (int j = 0; j < cube.numFaces(); ++j)
    for (int k = 0; k < 3; ++k)
      expected.insert(std::minmax(cube.faces(j, k), cube.faces(j, (k + 1) % 3)));
  for (int v = 0; v < 8; ++v) expected.insert({v, 8});
  std::set<std::pair<int, int>> got;
  for (int e = 0; e < edges.rows(); ++e) {
    EXPECT_LT(edges(e, 0), edges(e, 1));
    got.insert({edges(e, 0), edges(e, 1)});
  }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(volumeMeshEdges(*starVolumeMesh(makePolygonCage(test::lLoop()))).rows(), 2 * test::lLoop().rows());
}

TEST(VolumeMesh, NoStarForACageNotStarShapedFromItsCentroid) {
  // A U: its centroid lies in the gap between the arms, outside.
  Eigen::MatrixXd loop(8, 2);
  loop << 0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3;
  EXPECT_FALSE(starVolumeMesh(makePolygonCage(loop)));
}

// A checked mesh of the cube: its star, given with line numbers as if read from a file (vertex v on line 10 + v,
// simplex s on line 30 + s).
struct CubeCase {
  Cage cube = test::makeCube();
  VolumeMesh mesh = *starVolumeMesh(cube);
  VolumeMeshSource source{"cube.mesh", {}, {}};
  CubeCase() {
    for (int v = 0; v < mesh.numVertices(); ++v) source.vertexLines.push_back(10 + v);
    for (int s = 0; s < mesh.numSimplices(); ++s) source.simplexLines.push_back(30 + s);
  }
  void expectError(long line, const std::string& words) {
    try {
      checkVolumeMesh(mesh, cube, source);
      ADD_FAILURE() << "no error for: " << words;
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "cube.mesh");
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(e.problem().find(words), std::string::npos) << e.problem();
    }
  }
};

TEST(VolumeMesh, ReorientsNegativeElementsAndCountsThem) {
  CubeCase c;
  std::swap(c.mesh.simplices(3, 1), c.mesh.simplices(3, 2));
  std::swap(c.mesh.simplices(7, 0), c.mesh.simplices(7, 3));
  EXPECT_EQ(checkVolumeMesh(c.mesh, c.cube, c.source), 2);
  for (int s = 0; s < c.mesh.numSimplices(); ++s) EXPECT_GT(signedSimplexMeasure(c.mesh, s), 0);
}

TEST(VolumeMesh, RefusesAMeshWhoseFirstVerticesAreNotTheCagesNamingVertexAndDistance) {
  CubeCase c;
  c.mesh.vertices(5, 0) += 1e-6 * std::sqrt(12.0);  // 1e-6 cage diameters
  c.expectError(15, "vertex 6 is 1e-06 cage diameters from cage vertex 6");
}

TEST(VolumeMesh, AcceptsCageVerticesWithinTheTolerance) {
  CubeCase c;
  c.mesh.vertices(5, 0) += 1e-11;
  EXPECT_NO_THROW(checkVolumeMesh(c.mesh, c.cube, c.source));
}

TEST(VolumeMesh, RefusesAMeshReachingOutsideTheCage) {
  CubeCase c;
  // One more tetrahedron on the outside of cube face 0 (z = -1), apex below it.
  c.mesh.vertices.conservativeResize(10, 3);
  c.mesh.vertices.row(9) << -0.5, 0.5, -2;
  c.source.vertexLines.push_back(19);
  c.mesh.simplices.conservativeResize(13, 4);
  c.mesh.simplices.row(12) << 9, c.cube.faces(0, 0), c.cube.faces(0, 2), c.cube.faces(0, 1);
  c.source.simplexLines.push_back(42);
  c.expectError(42, "off the cage");
}

TEST(VolumeMesh, RefusesAMeshWithAHole) {
  CubeCase c;
  // Drop the last tetrahedron: its inner faces are now boundary faces through the inside of the cube.
  c.mesh.simplices.conservativeResize(11, 4);
  c.source.simplexLines.pop_back();
  try {
    checkVolumeMesh(c.mesh, c.cube, c.source);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("off the cage"), std::string::npos) << e.problem();
  }
}

TEST(VolumeMesh, RefusesFlatElements) {
  CubeCase c;
  c.mesh.simplices(4, 0) = c.mesh.simplices(4, 1);
  c.expectError(34, "tetrahedron 5 is degenerate");
}

TEST(VolumeMesh, RefusesAMeshCoveringTheCageTwice) {
  CubeCase c;
  const int s = c.mesh.numSimplices();
  c.mesh.simplices.conservativeResize(2 * s, 4);
  c.mesh.simplices.bottomRows(s) = c.mesh.simplices.topRows(s);
  c.source.simplexLines.resize(static_cast<std::size_t>(2 * s), 99);
  try {
    checkVolumeMesh(c.mesh, c.cube, c.source);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("shares a face"), std::string::npos) << e.problem();
  }
}

}  // namespace
}  // namespace somicage

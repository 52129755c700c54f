// shrinkTowardMesh (core/generation/cage_shrink.h): a loose cage moved toward the mesh still strictly encloses it by
// the exact check of cage_enclosure.h (every vertex inside, no edge crossing, no self-intersection), stays a valid
// cage, keeps its vertices `clearance` away, and gets tighter.
#include "generation/cage_shrink.h"

#include <gtest/gtest.h>

#include "cage/cage_validation.h"
#include "generation/cage_enclosure.h"
#include "test_shapes.h"

namespace somicage {
namespace {

struct Mesh {
  Eigen::MatrixXd vertices;
  Eigen::MatrixXi triangles;
};

// The unit icosphere, and (with a radius) a small sphere centred at `at`.
Mesh spheres(double radius = 0, const Eigen::RowVector3d& at = Eigen::RowVector3d::Zero()) {
  const Cage big = test::makeIcosphere(3);
  Mesh mesh{big.vertices, big.faces};
  if (radius == 0) return mesh;
  const Cage small = test::makeIcosphere(1);
  const int n = big.numVertices(), f = big.numFaces();
  mesh.vertices.conservativeResize(n + small.numVertices(), 3);
  mesh.triangles.conservativeResize(f + small.numFaces(), 3);
  mesh.vertices.bottomRows(small.numVertices()) = (radius * small.vertices).rowwise() + at;
  mesh.triangles.bottomRows(small.numFaces()) = small.faces.array() + n;
  return mesh;
}

// The octahedron with corners at distance r on the axes, (0, 0, r) first, outward.
Cage octahedron(double r) {
  Cage cage;
  cage.vertices.resize(6, 3);
  cage.vertices << 0, 0, r, r, 0, 0, 0, r, 0, -r, 0, 0, 0, -r, 0, 0, 0, -r;
  cage.faces.resize(8, 3);
  cage.faces << 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1, 5, 2, 1, 5, 3, 2, 5, 4, 3, 5, 1, 4;
  return cage;
}

void expectShrunkAndEnclosing(const Mesh& mesh, Cage cage, double clearance) {
  const Cage loose = cage;
  ASSERT_TRUE(validateCage(loose).valid());
  ASSERT_TRUE(checkEnclosure(loose, mesh.vertices, mesh.triangles).encloses());
  ShrinkOptions options;
  options.clearance = clearance;
  const int moves = shrinkTowardMesh(cage, mesh.vertices, mesh.triangles, options);
  EXPECT_GT(moves, 0);
  const EnclosureReport enclosure = checkEnclosure(cage, mesh.vertices, mesh.triangles);
  EXPECT_TRUE(enclosure.outsideVertices.empty()) << enclosure.outsideVertices.size() << " mesh vertices outside";
  EXPECT_TRUE(enclosure.crossedFaces.empty()) << enclosure.crossedFaces.size() << " faces crossed";
  EXPECT_TRUE(enclosure.selfIntersections.empty()) << enclosure.selfIntersections.size() << " self-intersections";
  const CageReport report = validateCage(cage);
  EXPECT_TRUE(report.valid());
  EXPECT_LT(report.signedVolume, 0.8 * validateCage(loose).signedVolume);  // tighter
  EXPECT_LT(hausdorffCageToMesh(cage, mesh.vertices, mesh.triangles),
            hausdorffCageToMesh(loose, mesh.vertices, mesh.triangles));
  // No vertex closer than the clearance to a mesh vertex (a bound from above on the distance to the mesh).
  for (int i = 0; i < cage.numVertices(); ++i)
    EXPECT_GE((mesh.vertices.rowwise() - cage.vertices.row(i)).rowwise().norm().minCoeff(), clearance * (1 - 1e-9));
}

TEST(CageShrink, ALooseCageAroundASphereShrinksAndStillEncloses) {
  Cage cage = test::makeIcosphere(1);  // 80 faces at radius 2.2
  cage.vertices *= 2.2;
  expectShrunkAndEnclosing(spheres(), cage, 0.05);
}

// The corner (0, 0, 3) of the octahedron heads for the unit sphere, 2 away. A sphere of radius 0.05 at (1, 1, 0.5)
// is farther from it (2.87) and lies between the face (corner, (3, 0, 0), (0, 3, 0)) and where that face would be
// with the corner at (0, 0, 1.05), 0.13 from the latter: the full move would leave it outside without any new face
// touching it. Only the swept-tetrahedron test sees that.
TEST(CageShrink, MovesDoNotJumpOverASmallSeparatePart) {
  expectShrunkAndEnclosing(spheres(0.05, Eigen::RowVector3d(1, 1, 0.5)), octahedron(3), 0.05);
}

}  // namespace
}  // namespace somicage

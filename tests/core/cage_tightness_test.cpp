// measureTightness (core/generation/cage_enclosure.h) against closed forms: a cube cage around a smaller cube and
// around a sphere (volume ratio, and the one-sided Hausdorff distance cage -> mesh, reached at the cage's corners), and
// an open mesh, which has no volume ratio.
#include <gtest/gtest.h>

#include <cmath>

#include "generation/cage_enclosure.h"
#include "test_shapes.h"

namespace somicage {
namespace {

// The cube [-s, s]^3 with outward faces.
Cage cube(double s) {
  Cage c = test::makeCube();
  c.vertices *= s;
  return c;
}

TEST(CageTightness, CubeAroundAHalfSizeCube) {
  const Cage mesh = cube(0.5);
  const CageTightness t = measureTightness(cube(1.0), mesh.vertices, mesh.faces);
  EXPECT_NEAR(t.volumeRatio, 8.0, 1e-12);
  // The corner (1, 1, 1) is farthest from the inner cube: |(0.5, 0.5, 0.5)| = sqrt(3) / 2; the mesh's diagonal is
  // sqrt(3), so half a diagonal.
  EXPECT_NEAR(t.hausdorff, 0.5, 1e-12);
}

TEST(CageTightness, CubeAroundASphere) {
  Cage sphere = test::makeIcosphere(4);  // 5120 faces, vertices on the unit sphere
  const CageTightness t = measureTightness(cube(2.0), sphere.vertices, sphere.faces);
  // Against the true unit sphere: volume 64 / (4 pi / 3); the corner is 2 sqrt(3) - 1 from it, in diagonals of its
  // bounding box (2 sqrt(3)). The inscribed polyhedron is slightly smaller (volume -0.4 %, extent -0.1 %).
  EXPECT_NEAR(t.volumeRatio, 64.0 / (4.0 * M_PI / 3.0), 0.01 * t.volumeRatio);
  const double diagonal = 2.0 * std::sqrt(3.0);
  EXPECT_NEAR(t.hausdorff, (2.0 * std::sqrt(3.0) - 1.0) / diagonal, 0.005);
}

TEST(CageTightness, OpenMeshHasNoVolumeRatio) {
  Cage mesh = cube(0.5);
  mesh.faces.conservativeResize(10, 3);  // two faces off: an open box
  const CageTightness t = measureTightness(cube(1.0), mesh.vertices, mesh.faces);
  EXPECT_TRUE(std::isnan(t.volumeRatio));
  EXPECT_NEAR(t.hausdorff, 0.5, 1e-12);  // the corners still see the same nearest points
}

}  // namespace
}  // namespace somicage
